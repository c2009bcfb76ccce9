#include "message_head.hpp"

#include <nlohmann/json.hpp>

#include <cstring>
#include <limits>

namespace carrom::load {

namespace {

using nlohmann::json;

proto::Error make_error(std::string_view code, std::string message) {
    return proto::Error{std::string(code), std::move(message)};
}

// The SAX handler: keeps the top-level fields of a head, passes over every other value (nested
// ones included) without storing it, and stops the parse once the head is known.
class HeadHandler {
public:
    // The outcome once sax_parse returned.
    proto::DecodedMessage<MessageHead> result() const {
        if (!error_.code.empty()) {
            return {{}, error_};
        }
        if (complete()) {
            return {head(), {}}; // stopped there
        }
        // The whole object was read: a delta, or a head that is not complete.
        if (!type_) {
            return {{}, missing_type()};
        }
        if (*type_ == "event") {
            return {
                {},
                make_error(proto::code::kBadField, "An event must have a string field 'kind'.")};
        }
        if (!keyframe_) {
            return {{},
                    make_error(proto::code::kBadField,
                               "A snapshot must have a boolean field 'keyframe'.")};
        }
        if (!t_s_) {
            return {{},
                    make_error(proto::code::kBadField, "A delta must have a number field 't'.")};
        }
        if (bad_due_ms_) {
            return {
                {},
                make_error(proto::code::kBadField, "A delta's field 'due_ms' must be an integer.")};
        }
        return {head(), {}};
    }

    // nlohmann::json's SAX interface (json_sax): returning false stops the parse.
    bool null() { return top_level(Value{}); }
    bool boolean(bool value) { return top_level(Value{Value::Kind::Boolean, value}); }
    bool number_integer(json::number_integer_t value) {
        return top_level(Value{Value::Kind::Integer, false, value, static_cast<double>(value)});
    }
    bool number_unsigned(json::number_unsigned_t value) {
        const bool fits =
            value <= static_cast<json::number_unsigned_t>(std::numeric_limits<std::int64_t>::max());
        return top_level(Value{fits ? Value::Kind::Integer : Value::Kind::Float, false,
                               fits ? static_cast<std::int64_t>(value) : 0,
                               static_cast<double>(value)});
    }
    bool number_float(json::number_float_t value, const json::string_t&) {
        return top_level(Value{Value::Kind::Float, false, 0, value});
    }
    bool string(json::string_t& value) {
        return top_level(Value{Value::Kind::String, false, 0, 0.0, &value});
    }
    bool binary(json::binary_t&) { return top_level(Value{}); }
    bool start_object(std::size_t) {
        if (depth_ == 1 && !top_level(Value{})) { // the field's value is an object
            return false;
        }
        ++depth_;
        return true;
    }
    bool key(json::string_t& name) {
        if (depth_ == 1) {
            field_ = name == "type"       ? Field::Type
                     : name == "kind"     ? Field::Kind
                     : name == "keyframe" ? Field::Keyframe
                     : name == "t"        ? Field::T
                     : name == "due_ms"   ? Field::DueMs
                                          : Field::Other;
        }
        return true;
    }
    bool end_object() {
        --depth_;
        return true;
    }
    bool start_array(std::size_t) {
        if (depth_ <= 1 && !top_level(Value{})) { // the message, or a field's value, is an array
            return false;
        }
        ++depth_;
        return true;
    }
    bool end_array() {
        --depth_;
        return true;
    }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) {
        error_ = make_error(proto::code::kMalformedJson,
                            "The message is not valid JSON (error at byte " +
                                std::to_string(position) + ").");
        return false;
    }

private:
    enum class Field { Other, Type, Kind, Keyframe, T, DueMs };

    // A value at any depth; only the top-level values of the head's fields are kept.
    struct Value {
        enum class Kind { Other, String, Boolean, Integer, Float };
        Kind kind = Kind::Other;
        bool boolean = false;
        std::int64_t integer = 0;
        double number = 0.0;                 // Integer and Float
        const std::string* string = nullptr; // String
    };

    static proto::Error missing_type() {
        return make_error(proto::code::kMissingType, "A message must have a string field 'type'.");
    }

    bool complete() const {
        if (!type_) {
            return false;
        }
        if (*type_ == "snapshot") { // a delta is read whole: its last number could be cut short
            return keyframe_ && *keyframe_;
        }
        if (*type_ == "event") {
            return kind_.has_value();
        }
        return true;
    }

    MessageHead head() const {
        MessageHead out;
        out.type = *type_;
        if (*type_ == "event") {
            out.kind = kind_.value_or("");
        } else if (*type_ == "snapshot" && !*keyframe_) {
            out.snapshot = SnapshotFields{false, *t_s_, due_ms_};
        } else if (*type_ == "snapshot") {
            out.snapshot = SnapshotFields{true, 0.0, std::nullopt};
        }
        return out;
    }

    // Keeps a top-level field's value (a later duplicate key replaces an earlier one); false
    // stops the parse: at an error, or once the head is known.
    bool top_level(const Value& value) {
        if (depth_ == 0) {
            error_ = make_error(proto::code::kNotObject, "A message must be a JSON object.");
            return false;
        }
        if (depth_ != 1) {
            return true;
        }
        const bool is_number =
            value.kind == Value::Kind::Integer || value.kind == Value::Kind::Float;
        switch (field_) {
        case Field::Type:
            if (value.kind != Value::Kind::String) {
                error_ = missing_type();
                return false;
            }
            type_ = *value.string;
            break;
        case Field::Kind:
            kind_ = value.kind == Value::Kind::String ? std::optional(*value.string) : std::nullopt;
            break;
        case Field::Keyframe:
            keyframe_ =
                value.kind == Value::Kind::Boolean ? std::optional(value.boolean) : std::nullopt;
            break;
        case Field::T:
            t_s_ = is_number ? std::optional(value.number) : std::nullopt;
            break;
        case Field::DueMs:
            bad_due_ms_ = value.kind != Value::Kind::Integer;
            due_ms_ = bad_due_ms_ ? std::nullopt : std::optional(value.integer);
            break;
        case Field::Other:
            return true;
        }
        return !complete();
    }

    int depth_ = 0;              // 1: inside the top-level object
    Field field_ = Field::Other; // of the latest top-level key
    std::optional<std::string> type_;
    std::optional<std::string> kind_;
    std::optional<bool> keyframe_;
    std::optional<double> t_s_;
    std::optional<std::int64_t> due_ms_;
    bool bad_due_ms_ = false;
    proto::Error error_;
};

} // namespace

proto::DecodedMessage<MessageHead> read_message_head(std::string_view text) {
    // nlohmann's lexer reads a NUL byte as the end of the input; valid JSON never holds one.
    if (const auto* nul = static_cast<const char*>(std::memchr(text.data(), '\0', text.size()))) {
        return {{},
                make_error(proto::code::kMalformedJson,
                           "The message is not valid JSON (a NUL byte at byte " +
                               std::to_string(nul - text.data()) + ").")};
    }
    HeadHandler handler;
    // false when the handler stopped it: once the head was known, or at an error it kept.
    json::sax_parse(text.data(), text.data() + text.size(), &handler);
    return handler.result();
}

} // namespace carrom::load
