#include "message_head.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace carrom::load {

namespace {

proto::Error make_error(std::string_view code, std::string message) {
    return proto::Error{std::string(code), std::move(message)};
}

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

// The UTF-16 unit of four hexadecimal digits (either case) at `at`; -1 unless all four are.
int hex4_at(std::string_view text, std::size_t at) {
    unsigned unit = 0;
    const char* first = text.data() + std::min(at, text.size());
    const char* last = text.data() + std::min(at + 4, text.size());
    const auto [ptr, ec] = std::from_chars(first, last, unit, 16);
    return ec == std::errc{} && ptr == first + 4 ? static_cast<int>(unit) : -1;
}

void append_utf8(std::string& out, std::uint32_t code_point) {
    const auto byte = [](std::uint32_t value) { return static_cast<char>(value); };
    if (code_point < 0x80) {
        out += byte(code_point);
    } else if (code_point < 0x800) {
        out += byte(0xC0 | (code_point >> 6));
        out += byte(0x80 | (code_point & 0x3F));
    } else if (code_point < 0x10000) {
        out += byte(0xE0 | (code_point >> 12));
        out += byte(0x80 | ((code_point >> 6) & 0x3F));
        out += byte(0x80 | (code_point & 0x3F));
    } else {
        out += byte(0xF0 | (code_point >> 18));
        out += byte(0x80 | ((code_point >> 12) & 0x3F));
        out += byte(0x80 | ((code_point >> 6) & 0x3F));
        out += byte(0x80 | (code_point & 0x3F));
    }
}

// One pass over the text that checks the JSON grammar of RFC 8259 (strings: escapes, no control
// characters, well-formed UTF-8; numbers: the JSON form) and converts only the values of the
// head's top-level fields; every other value is passed over without being converted or stored.
class HeadScanner {
public:
    explicit HeadScanner(std::string_view text) : text_(text) {}

    proto::DecodedMessage<MessageHead> read() {
        if (!top_object() && !error_.code.empty()) {
            return {{}, error_};
        }
        if (complete()) {
            return {head(), {}}; // stopped there, or a delta read whole
        }
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
        return {{},
                make_error(proto::code::kBadField, "A delta's field 'due_ms' must be an integer.")};
    }

private:
    enum class Field { Other, Type, Kind, Keyframe, T, DueMs };
    static constexpr int kMaxDepth = 64; // nesting of objects and arrays; messages use 3

    static proto::Error missing_type() {
        return make_error(proto::code::kMissingType, "A message must have a string field 'type'.");
    }

    // Whether the head is known: a message is read no further (a delta is read whole).
    bool complete() const {
        if (!type_) {
            return false;
        }
        if (*type_ == "snapshot") {
            return keyframe_ && (*keyframe_ || (read_whole_ && t_s_ && !bad_due_ms_));
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

    // false: an error (error_ set) or the head complete before the end.
    bool top_object() {
        skip_whitespace();
        if (at_end() || text_[pos_] != '{') {
            const bool json_value =
                !at_end() &&
                std::string_view("[\"-0123456789tfn").find(text_[pos_]) != std::string_view::npos;
            return json_value ? refuse(proto::code::kNotObject, "A message must be a JSON object.")
                              : fail();
        }
        ++pos_;
        skip_whitespace();
        if (!at_end() && text_[pos_] == '}') {
            ++pos_;
        } else {
            for (;;) {
                std::string key;
                if (at_end() || text_[pos_] != '"') {
                    return fail();
                }
                if (!string(&key) || !colon() || !field(field_of(key))) {
                    return false;
                }
                skip_whitespace();
                if (!at_end() && text_[pos_] == ',') {
                    ++pos_;
                    skip_whitespace();
                    continue;
                }
                if (at_end() || text_[pos_] != '}') {
                    return fail();
                }
                ++pos_;
                break;
            }
        }
        skip_whitespace();
        if (!at_end()) {
            return fail();
        }
        read_whole_ = true;
        return true;
    }

    static Field field_of(const std::string& key) {
        return key == "type"       ? Field::Type
               : key == "kind"     ? Field::Kind
               : key == "keyframe" ? Field::Keyframe
               : key == "t"        ? Field::T
               : key == "due_ms"   ? Field::DueMs
                                   : Field::Other;
    }

    // A top-level field's value; a later duplicate key replaces an earlier one. false: an error,
    // or the head complete.
    bool field(Field which) {
        const char first = at_end() ? '\0' : text_[pos_];
        const bool is_number = first == '-' || is_digit(first);
        std::string_view number_text;
        switch (which) {
        case Field::Other:
            return value(1);
        case Field::Type: {
            std::string type;
            if (first != '"') {
                return refuse(proto::code::kMissingType,
                              "A message must have a string field 'type'.");
            }
            if (!string(&type)) {
                return false;
            }
            type_ = std::move(type);
            break;
        }
        case Field::Kind: {
            std::string kind;
            if (first == '"' ? !string(&kind) : !value(1)) {
                return false;
            }
            kind_ = first == '"' ? std::optional(std::move(kind)) : std::nullopt;
            break;
        }
        case Field::Keyframe:
            if (!value(1)) {
                return false;
            }
            keyframe_ = first == 't'   ? std::optional(true)
                        : first == 'f' ? std::optional(false)
                                       : std::nullopt;
            break;
        case Field::T: {
            if (is_number ? !number(&number_text) : !value(1)) {
                return false;
            }
            double t = 0.0;
            const auto end = number_text.data() + number_text.size();
            t_s_ = is_number && std::from_chars(number_text.data(), end, t).ec == std::errc{}
                       ? std::optional(t)
                       : std::nullopt;
            break;
        }
        case Field::DueMs: {
            if (is_number ? !number(&number_text) : !value(1)) {
                return false;
            }
            std::int64_t due = 0;
            const auto end = number_text.data() + number_text.size();
            const auto [ptr, ec] = std::from_chars(number_text.data(), end, due);
            bad_due_ms_ = !is_number || ec != std::errc{} || ptr != end;
            due_ms_ = bad_due_ms_ ? std::nullopt : std::optional(due);
            break;
        }
        }
        return !complete();
    }

    // Passes over one value nested `depth` deep.
    bool value(int depth) {
        if (at_end()) {
            return fail();
        }
        switch (text_[pos_]) {
        case '{':
            return container(depth + 1, '}', true);
        case '[':
            return container(depth + 1, ']', false);
        case '"':
            return string(nullptr);
        case 't':
            return literal("true");
        case 'f':
            return literal("false");
        case 'n':
            return literal("null");
        default:
            return number(nullptr);
        }
    }

    // An object (members "key": value) or an array (values) at the opening bracket.
    bool container(int depth, char close, bool members) {
        if (depth > kMaxDepth) {
            return fail();
        }
        ++pos_;
        skip_whitespace();
        if (!at_end() && text_[pos_] == close) {
            ++pos_;
            return true;
        }
        for (;;) {
            if (members && (at_end() || text_[pos_] != '"')) {
                return fail();
            }
            if (members && (!string(nullptr) || !colon())) {
                return false;
            }
            if (!value(depth)) {
                return false;
            }
            skip_whitespace();
            if (at_end()) {
                return fail();
            }
            if (text_[pos_] == close) {
                ++pos_;
                return true;
            }
            if (text_[pos_] != ',') {
                return fail();
            }
            ++pos_;
            skip_whitespace();
        }
    }

    bool colon() {
        skip_whitespace();
        if (at_end() || text_[pos_] != ':') {
            return fail();
        }
        ++pos_;
        skip_whitespace();
        return true;
    }

    // A string at its opening quote; its content into `out` when given.
    bool string(std::string* out) {
        ++pos_;
        const std::size_t start = pos_;
        bool escaped = false;
        while (!at_end()) {
            const auto c = static_cast<unsigned char>(text_[pos_]);
            if (c == '"') {
                if (out != nullptr) {
                    *out = escaped ? unescape(text_.substr(start, pos_ - start))
                                   : std::string(text_.substr(start, pos_ - start));
                }
                ++pos_;
                return true;
            }
            if (c < 0x20) {
                return fail();
            }
            if (c == '\\') {
                escaped = true;
                if (!escape()) {
                    return false;
                }
            } else if (c >= 0x80) {
                if (!utf8_sequence()) {
                    return false;
                }
            } else {
                ++pos_;
            }
        }
        return fail();
    }

    // An escape at its backslash; a high surrogate must be followed by a low one.
    bool escape() {
        ++pos_;
        if (at_end()) {
            return fail();
        }
        if (std::string_view("\"\\/bfnrt").find(text_[pos_]) != std::string_view::npos) {
            ++pos_;
            return true;
        }
        int unit = 0;
        if (!hex4(unit)) {
            return false;
        }
        if (unit >= 0xDC00 && unit <= 0xDFFF) {
            return fail();
        }
        if (unit >= 0xD800 && unit <= 0xDBFF) {
            if (pos_ + 1 >= text_.size() || text_[pos_] != '\\' || text_[pos_ + 1] != 'u') {
                return fail();
            }
            ++pos_;
            int low = 0;
            if (!hex4(low)) {
                return false;
            }
            if (low < 0xDC00 || low > 0xDFFF) {
                return fail();
            }
        }
        return true;
    }

    // "uXXXX" at its u.
    bool hex4(int& unit) {
        if (text_[pos_] != 'u') {
            return fail();
        }
        ++pos_;
        unit = hex4_at(text_, pos_);
        if (unit < 0) {
            while (!at_end() && std::isxdigit(static_cast<unsigned char>(text_[pos_]))) {
                ++pos_; // the error names the first byte that is not a digit
            }
            return fail();
        }
        pos_ += 4;
        return true;
    }

    // The content of a string the scan found well-formed, its escapes decoded.
    static std::string unescape(std::string_view raw) {
        std::string out;
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] != '\\') {
                out += raw[i];
                continue;
            }
            const char e = raw[++i];
            const std::string_view from = "\"\\/bfnrt";
            const std::string_view to = "\"\\/\b\f\n\r\t";
            if (e != 'u') {
                out += to[from.find(e)];
                continue;
            }
            auto code_point = static_cast<std::uint32_t>(hex4_at(raw, i + 1));
            i += 4;
            if (code_point >= 0xD800 && code_point <= 0xDBFF) {
                const auto low = static_cast<std::uint32_t>(hex4_at(raw, i + 3));
                code_point = 0x10000 + ((code_point - 0xD800) << 10) + (low - 0xDC00);
                i += 6;
            }
            append_utf8(out, code_point);
        }
        return out;
    }

    // One UTF-8 sequence (RFC 3629) at its first byte, 0x80 or above.
    bool utf8_sequence() {
        const auto at = [&](std::size_t k) -> unsigned char {
            return pos_ + k < text_.size() ? static_cast<unsigned char>(text_[pos_ + k]) : 0;
        };
        const unsigned char lead = at(0);
        int more = 0;
        unsigned char low = 0x80;
        unsigned char high = 0xBF; // of the second byte
        if (lead >= 0xC2 && lead <= 0xDF) {
            more = 1;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            more = 2;
            low = lead == 0xE0 ? 0xA0 : 0x80;
            high = lead == 0xED ? 0x9F : 0xBF;
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            more = 3;
            low = lead == 0xF0 ? 0x90 : 0x80;
            high = lead == 0xF4 ? 0x8F : 0xBF;
        } else {
            return fail();
        }
        for (int k = 1; k <= more; ++k) {
            const unsigned char c = at(static_cast<std::size_t>(k));
            if (c < (k == 1 ? low : 0x80) || c > (k == 1 ? high : 0xBF)) {
                pos_ += static_cast<std::size_t>(k);
                return fail();
            }
        }
        pos_ += static_cast<std::size_t>(more) + 1;
        return true;
    }

    // A number in the JSON form (-? int frac? exp?); its text into `out` when given.
    bool number(std::string_view* out) {
        const std::size_t start = pos_;
        const auto digits = [&] {
            const std::size_t from = pos_;
            while (!at_end() && is_digit(text_[pos_])) {
                ++pos_;
            }
            return pos_ > from;
        };
        if (!at_end() && text_[pos_] == '-') {
            ++pos_;
        }
        if (!at_end() && text_[pos_] == '0') {
            ++pos_;
        } else if (!digits()) {
            return fail();
        }
        if (!at_end() && text_[pos_] == '.') {
            ++pos_;
            if (!digits()) {
                return fail();
            }
        }
        if (!at_end() && (text_[pos_] == 'e' || text_[pos_] == 'E')) {
            ++pos_;
            if (!at_end() && (text_[pos_] == '+' || text_[pos_] == '-')) {
                ++pos_;
            }
            if (!digits()) {
                return fail();
            }
        }
        if (out != nullptr) {
            *out = text_.substr(start, pos_ - start);
        }
        return true;
    }

    bool literal(std::string_view word) {
        for (const char c : word) {
            if (at_end() || text_[pos_] != c) {
                return fail();
            }
            ++pos_;
        }
        return true;
    }

    void skip_whitespace() {
        while (!at_end() && (text_[pos_] == ' ' || text_[pos_] == '\n' || text_[pos_] == '\r' ||
                             text_[pos_] == '\t')) {
            ++pos_;
        }
    }

    bool at_end() const { return pos_ >= text_.size(); }

    // The text breaks the grammar at pos_ (its 1-based byte: the end of the text is size + 1).
    bool fail() {
        return refuse(proto::code::kMalformedJson, "The message is not valid JSON (error at byte " +
                                                       std::to_string(pos_ + 1) + ").");
    }

    bool refuse(std::string_view code, std::string message) {
        error_ = make_error(code, std::move(message));
        return false;
    }

    std::string_view text_;
    std::size_t pos_ = 0;     // the next byte to read
    bool read_whole_ = false; // the top-level object ended and nothing followed it
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
    return HeadScanner(text).read();
}

} // namespace carrom::load
