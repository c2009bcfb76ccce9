#include "message_head.hpp"

#include <simdjson.h>

#include <string>
#include <utility>

namespace carrom::load {

namespace {

namespace ondemand = simdjson::ondemand;

// Nesting of objects and arrays that a message may have, the message's object being the first
// level; the server's messages use 3.
constexpr int kMaxDepth = 64;

proto::Error make_error(std::string_view code, std::string message) {
    return proto::Error{std::string(code), std::move(message)};
}

// "The message is not valid JSON: " and simdjson's sentence for `error`, without its final stop.
std::string not_json(simdjson::error_code error) {
    std::string message = "The message is not valid JSON: ";
    message += simdjson::error_message(error);
    if (message.ends_with('.')) {
        message.pop_back();
    }
    return message;
}

// Reads one message's head with simdjson's On-Demand parser. On-Demand checks only what it visits,
// so every value it passes over before the head is known is visited whole (`check_value`): a
// message is refused as malformed at the same values as a full parse up to that point.
class HeadReader {
public:
    HeadReader(ondemand::document& document, const char* text_begin)
        : document_(document), text_begin_(text_begin) {}

    proto::DecodedMessage<MessageHead> read() {
        ondemand::json_type top_type;
        if (const auto error = document_.type().get(top_type)) {
            return {{}, malformed(error)};
        }
        if (top_type != ondemand::json_type::object) {
            return {{}, make_error(proto::code::kNotObject, "A message must be a JSON object.")};
        }
        ondemand::object object;
        if (const auto error = document_.get_object().get(object)) {
            return {{}, malformed(error)};
        }
        for (auto field_result : object) {
            ondemand::field field;
            std::string_view key;
            if (auto error = std::move(field_result).get(field);
                error || (error = field.unescaped_key().get(key))) {
                return {{}, malformed(error)};
            }
            if (const auto error = read_field(key, field.value())) {
                return {{}, malformed(error)};
            }
            if (complete(false)) {
                return {head(), {}}; // the head is known before the end: read no further
            }
        }
        // The document's iterator stands on the first token after the object, if there is one.
        if (const char* trailing = nullptr; !document_.current_location().get(trailing)) {
            return {{}, malformed(simdjson::TRAILING_CONTENT)};
        }
        if (complete(true)) {
            return {head(), {}};
        }
        return {{}, missing_field()};
    }

private:
    // Reads the value of the top-level field `key` if the head uses it, and checks it whole.
    simdjson::error_code read_field(std::string_view key, ondemand::value value) {
        ondemand::json_type type;
        if (const auto error = value.type().get(type)) {
            return error;
        }
        const bool is_string = type == ondemand::json_type::string;
        if (key == "type" && is_string) {
            return read_string(value, type_);
        }
        if (key == "kind" && is_string) {
            return read_string(value, kind_);
        }
        if (key == "keyframe" && type == ondemand::json_type::boolean) {
            bool keyframe = false;
            const auto error = read_bool(value, keyframe);
            keyframe_ = keyframe;
            return error;
        }
        if ((key == "t" || key == "due_ms") && type == ondemand::json_type::number) {
            ondemand::number number;
            if (const auto error = value.get_number().get(number)) {
                return error;
            }
            if (key == "t") {
                t_s_ = number.as_double();
            } else if (number.is_int64()) {
                due_ms_ = number.get_int64();
                bad_due_ms_ = false;
            } else {
                bad_due_ms_ = true;
            }
            return simdjson::SUCCESS;
        }
        if (key == "due_ms") {
            bad_due_ms_ = true;
        }
        return check_value(value, 2);
    }

    static simdjson::error_code read_string(ondemand::value value,
                                            std::optional<std::string>& out) {
        std::string_view text;
        const auto error = value.get_string().get(text);
        out = std::string(text);
        return error;
    }

    // simdjson reports a misspelt `true` or `false` as a value of another type; this names it.
    static simdjson::error_code read_bool(ondemand::value value, bool& out) {
        if (value.get_bool().get(out) == simdjson::SUCCESS) {
            return simdjson::SUCCESS;
        }
        return value.raw_json_token().starts_with('t') ? simdjson::T_ATOM_ERROR
                                                       : simdjson::F_ATOM_ERROR;
    }

    // Visits `value` (at nesting level `depth`) whole, converting each scalar, so that On-Demand
    // checks its grammar.
    static simdjson::error_code check_value(ondemand::value value, int depth) {
        ondemand::json_type type;
        if (const auto error = value.type().get(type)) {
            return error;
        }
        const bool nests =
            type == ondemand::json_type::array || type == ondemand::json_type::object;
        if (nests && depth > kMaxDepth) {
            return simdjson::DEPTH_ERROR;
        }
        switch (type) {
        case ondemand::json_type::array: {
            ondemand::array array;
            if (const auto error = value.get_array().get(array)) {
                return error;
            }
            for (auto element : array) {
                ondemand::value element_value;
                auto error = std::move(element).get(element_value);
                if (error || (error = check_value(element_value, depth + 1))) {
                    return error;
                }
            }
            return simdjson::SUCCESS;
        }
        case ondemand::json_type::object: {
            ondemand::object object;
            auto error = value.get_object().get(object);
            for (auto field_result = object.begin(); !error && field_result != object.end();
                 ++field_result) {
                ondemand::field field;
                std::string_view key; // unescaped to check its escapes
                if (!(error = std::move(*field_result).get(field)) &&
                    !(error = field.unescaped_key().get(key))) {
                    error = check_value(field.value(), depth + 1);
                }
            }
            return error;
        }
        case ondemand::json_type::number:
            return value.get_number().error();
        case ondemand::json_type::string:
            return value.get_string().error();
        case ondemand::json_type::boolean: {
            bool ignored = false;
            return read_bool(value, ignored);
        }
        case ondemand::json_type::null: {
            bool is_null = false;
            const auto error = value.is_null().get(is_null);
            return error ? error : is_null ? simdjson::SUCCESS : simdjson::N_ATOM_ERROR;
        }
        }
        return simdjson::INCORRECT_TYPE;
    }

    // Whether the head is known; `read_whole`: the object has been read to its end.
    bool complete(bool read_whole) const {
        if (!type_) {
            return false;
        }
        if (*type_ == "snapshot") {
            return keyframe_ && (*keyframe_ || (read_whole && t_s_ && !bad_due_ms_));
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
            out.kind = *kind_;
        } else if (*type_ == "snapshot") {
            out.snapshot = *keyframe_ ? SnapshotFields{true, 0.0, std::nullopt}
                                      : SnapshotFields{false, *t_s_, due_ms_};
        }
        return out;
    }

    // The error of a message read whole whose head is not complete.
    proto::Error missing_field() const {
        if (!type_) {
            return make_error(proto::code::kMissingType,
                              "A message must have a string field 'type'.");
        }
        if (*type_ == "event") {
            return make_error(proto::code::kBadField, "An event must have a string field 'kind'.");
        }
        if (!keyframe_) {
            return make_error(proto::code::kBadField,
                              "A snapshot must have a boolean field 'keyframe'.");
        }
        if (!t_s_) {
            return make_error(proto::code::kBadField, "A delta must have a number field 't'.");
        }
        return make_error(proto::code::kBadField, "A delta's field 'due_ms' must be an integer.");
    }

    // simdjson's sentence, and the byte (1-based) where its iterator stands when that is where the
    // error is (not for a document that ends early: simdjson finds that before it reads a value).
    proto::Error malformed(simdjson::error_code error) {
        std::string message = not_json(error);
        const char* location = nullptr;
        if (error != simdjson::INCOMPLETE_ARRAY_OR_OBJECT &&
            !document_.current_location().get(location)) {
            message += " (byte " + std::to_string(location - text_begin_ + 1) + ")";
        }
        return make_error(proto::code::kMalformedJson, message + ".");
    }

    ondemand::document& document_;
    const char* text_begin_;
    std::optional<std::string> type_;
    std::optional<std::string> kind_;
    std::optional<bool> keyframe_;
    std::optional<double> t_s_;
    std::optional<std::int64_t> due_ms_;
    bool bad_due_ms_ = false;
};

} // namespace

proto::DecodedMessage<MessageHead> read_message_head(std::string_view text) {
    // One parser and one padded copy of the text per thread, reused: their buffers grow to the
    // largest message read and are not allocated again.
    thread_local ondemand::parser parser;
    thread_local std::string padded;
    padded.reserve(text.size() + simdjson::SIMDJSON_PADDING);
    padded.assign(text);
    ondemand::document document;
    if (const auto error = parser
                               .iterate(simdjson::padded_string_view(padded.data(), text.size(),
                                                                     padded.capacity()))
                               .get(document)) {
        return {{}, make_error(proto::code::kMalformedJson, not_json(error) + ".")};
    }
    return HeadReader(document, padded.data()).read();
}

} // namespace carrom::load
