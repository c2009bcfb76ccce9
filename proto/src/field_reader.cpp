#include "field_reader.hpp"

#include <cmath>
#include <cstdio>

namespace carrom::proto::detail {

using nlohmann::json;

namespace {

std::string format_number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

bool has_control_character(std::string_view text) {
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            return true;
        }
    }
    return false;
}

} // namespace

// Built by appending: `"[" + std::string(...)` inserts at the front of a temporary, where g++ 12
// at -O3 reports a false -Wrestrict overlap (GCC bug 105329).
std::string range_text(double min, double max) {
    std::string out = "[";
    out += format_number(min);
    out += ", ";
    out += format_number(max);
    out += ']';
    return out;
}

std::string range_text(std::int64_t min, std::int64_t max) {
    std::string out = "[";
    out += std::to_string(min);
    out += ", ";
    out += std::to_string(max);
    out += ']';
    return out;
}

bool read_integer(const json& value, std::int64_t min, std::int64_t max, std::int64_t& out) {
    if (value.is_number_unsigned()) {
        const auto v = value.get<std::uint64_t>();
        if (v > static_cast<std::uint64_t>(max)) {
            return false;
        }
        out = static_cast<std::int64_t>(v);
        return out >= min;
    }
    if (value.is_number_integer()) {
        const auto v = value.get<std::int64_t>();
        if (v < min || v > max) {
            return false;
        }
        out = v;
        return true;
    }
    return false;
}

bool read_number(const json& value, double min, double max, double& out) {
    if (!value.is_number()) {
        return false;
    }
    const double v = value.get<double>();
    if (!std::isfinite(v) || v < min || v > max) {
        return false;
    }
    out = v;
    return true;
}

FieldReader::FieldReader(const json& object, std::string path)
    : object_(object), path_(std::move(path)) {}

std::string FieldReader::field_name(std::string_view key) const {
    return path_ + std::string(key);
}

void FieldReader::fail(std::string_view key, std::string_view requirement) {
    if (error_) {
        return;
    }
    error_ = Error{std::string(code::kBadField),
                   "field '" + field_name(key) + "' " + std::string(requirement) + "."};
}

void FieldReader::merge(const FieldReader& child) {
    if (!error_ && child.error_) {
        error_ = child.error_;
    }
}

bool FieldReader::has(std::string_view key) const {
    return object_.is_object() && object_.contains(key);
}

const json* FieldReader::find(std::string_view key) {
    if (error_) {
        return nullptr;
    }
    if (!object_.is_object()) {
        fail(key, "belongs to a value that must be an object");
        return nullptr;
    }
    const auto it = object_.find(key);
    if (it == object_.end()) {
        fail(key, "is required");
        return nullptr;
    }
    return &*it;
}

std::int64_t FieldReader::integer(std::string_view key, std::int64_t min, std::int64_t max) {
    const json* value = find(key);
    std::int64_t out = 0;
    if (value != nullptr && !read_integer(*value, min, max, out)) {
        fail(key, "must be an integer in " + range_text(min, max));
        return 0;
    }
    return out;
}

int FieldReader::small_int(std::string_view key, int min, int max) {
    return static_cast<int>(integer(key, min, max));
}

double FieldReader::number(std::string_view key, double min, double max) {
    const json* value = find(key);
    double out = 0.0;
    if (value != nullptr && !read_number(*value, min, max, out)) {
        fail(key, "must be a finite number in " + range_text(min, max));
        return 0.0;
    }
    return out;
}

bool FieldReader::boolean(std::string_view key) {
    const json* value = find(key);
    if (value == nullptr) {
        return false;
    }
    if (!value->is_boolean()) {
        fail(key, "must be true or false");
        return false;
    }
    return value->get<bool>();
}

std::string FieldReader::text(std::string_view key, std::size_t min_bytes, std::size_t max_bytes) {
    const json* value = find(key);
    if (value == nullptr) {
        return {};
    }
    const std::string* text = value->get_ptr<const std::string*>();
    if (text == nullptr) {
        fail(key, "must be a string");
        return {};
    }
    if (text->size() < min_bytes || text->size() > max_bytes) {
        fail(key, min_bytes == max_bytes
                      ? "must be exactly " + std::to_string(min_bytes) + " bytes long"
                      : "must be " + std::to_string(min_bytes) + " to " +
                            std::to_string(max_bytes) + " bytes long");
        return {};
    }
    if (has_control_character(*text)) {
        fail(key, "must not contain control characters");
        return {};
    }
    return *text;
}

const json* FieldReader::object(std::string_view key) {
    const json* value = find(key);
    if (value != nullptr && !value->is_object()) {
        fail(key, "must be an object");
        return nullptr;
    }
    return value;
}

const json* FieldReader::array(std::string_view key, std::size_t max_items) {
    const json* value = find(key);
    if (value == nullptr) {
        return nullptr;
    }
    if (!value->is_array()) {
        fail(key, "must be an array");
        return nullptr;
    }
    if (value->size() > max_items) {
        fail(key, "must have at most " + std::to_string(max_items) + " items");
        return nullptr;
    }
    return value;
}

std::vector<int> FieldReader::int_array(std::string_view key, int min, int max,
                                        std::size_t max_items) {
    std::vector<int> out;
    const json* values = array(key, max_items);
    if (values == nullptr) {
        return out;
    }
    out.reserve(values->size());
    for (const json& item : *values) {
        std::int64_t v = 0;
        if (!read_integer(item, min, max, v)) {
            fail(key, "must hold integers in " + range_text(std::int64_t{min}, std::int64_t{max}));
            return {};
        }
        out.push_back(static_cast<int>(v));
    }
    return out;
}

} // namespace carrom::proto::detail
