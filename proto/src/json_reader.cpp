#include "json_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

namespace carrom::proto::detail {

using nlohmann::json;

namespace {

// Wire ranges print numbers with %g ("[0, 1e+06]").
std::string wire_number(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

// Document ranges print the shortest text that reads back as the same double ("1000000").
std::string document_number(double value) {
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end);
}

// Built by appending: `"[" + std::string(...)` inserts at the front of a temporary, where g++ 12
// at -O3 reports a false -Wrestrict overlap (GCC bug 105329).
std::string interval(const std::string& lo, const std::string& hi, bool lo_open) {
    std::string out = lo_open ? "(" : "[";
    out += lo;
    out += ", ";
    out += hi;
    out += ']';
    return out;
}

std::string integer_interval(std::int64_t min, std::int64_t max) {
    return interval(std::to_string(min), std::to_string(max), false);
}

bool has_control_character(std::string_view text) {
    return std::any_of(text.begin(), text.end(), [](char c) {
        const auto byte = static_cast<unsigned char>(c);
        return byte < 0x20 || byte == 0x7f;
    });
}

// How a Document sentence names the value at path.
std::string name_of(const std::string& path) {
    return path.empty() ? "the document" : path;
}

const char* type_name(const json& value) {
    return value.is_number() ? "a number" : value.type_name(); // "string", "object", ...
}

} // namespace

std::string field_path(const std::string& parent, std::string_view name) {
    return parent.empty() ? std::string(name) : parent + "." + std::string(name);
}

std::string index_path(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

bool read_integer(const json& value, std::int64_t min, std::int64_t max, std::int64_t& out) {
    if (value.is_number_unsigned()) {
        const auto v = value.get<std::uint64_t>();
        if (v > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()) ||
            static_cast<std::int64_t>(v) < min || static_cast<std::int64_t>(v) > max) {
            return false;
        }
        out = static_cast<std::int64_t>(v);
        return true;
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

JsonReader::JsonReader(const json& object, std::string path, Wording wording)
    : object_(object), path_(std::move(path)), wording_(wording) {}

JsonReader JsonReader::nested(const json& value, std::string path) const {
    JsonReader out(value, std::move(path), wording_);
    out.error_ = error_;
    return out;
}

void JsonReader::merge(const std::optional<Error>& error) {
    if (!error_ && error) {
        error_ = error;
    }
}

void JsonReader::reject(std::string_view document_code, const std::string& path,
                        std::string_view wire_requirement, std::string document_sentence) {
    if (error_) {
        return;
    }
    if (wording_ == Wording::Wire) {
        error_ = Error{std::string(code::kBadField),
                       "field '" + path + "' " + std::string(wire_requirement) + ".", path};
    } else {
        error_ = Error{std::string(document_code), std::move(document_sentence), path};
    }
}

void JsonReader::wrong_type(const json& value, const std::string& path, std::string_view expected,
                            std::string_view wire_requirement) {
    const std::string must_be = "must be " + std::string(expected);
    reject(scene_code::kWrongType, path, wire_requirement.empty() ? must_be : wire_requirement,
           name_of(path) + " " + must_be + ", not " + type_name(value));
}

void JsonReader::fail(std::string_view key, std::string_view requirement,
                      std::string_view document_code) {
    fail_at(path_of(key), requirement, document_code);
}

void JsonReader::fail_at(const std::string& path, std::string_view requirement,
                         std::string_view document_code) {
    reject(document_code, path, requirement, name_of(path) + " " + std::string(requirement));
}

bool JsonReader::only_keys(std::span<const std::string_view> allowed) {
    if (!ok()) {
        return false;
    }
    if (!object_.is_object()) {
        wrong_type(object_, path_, "an object", "must be an object");
        return false;
    }
    for (const auto& item : object_.items()) {
        const std::string& key = item.key();
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            reject(scene_code::kUnknownField, path_of(key), "is not a known field",
                   "unknown field '" + key + "' in " + name_of(path_));
            return false;
        }
    }
    return true;
}

bool JsonReader::require(std::initializer_list<std::string_view> keys) {
    for (std::string_view key : keys) {
        find(key);
    }
    return ok();
}

bool JsonReader::has(std::string_view key) const {
    return ok() && object_.is_object() && object_.contains(key);
}

const json* JsonReader::find(std::string_view key) {
    if (!ok()) {
        return nullptr;
    }
    // A value that is not an object holds no field: Document wording reports the field missing.
    const auto it = object_.is_object() ? object_.find(key) : object_.end();
    if (it == object_.end()) {
        reject(scene_code::kMissingField, path_of(key),
               object_.is_object() ? "is required" : "belongs to a value that must be an object",
               name_of(path_) + " needs the field '" + std::string(key) + "'");
        return nullptr;
    }
    return &*it;
}

const json* JsonReader::find_optional(std::string_view key) const {
    if (!has(key)) {
        return nullptr;
    }
    const json& value = object_[std::string(key)];
    return value.is_null() ? nullptr : &value;
}

std::int64_t JsonReader::integer(std::string_view key, std::int64_t min, std::int64_t max) {
    const json* value = find(key);
    return value == nullptr ? 0 : integer_at(*value, path_of(key), min, max);
}

int JsonReader::small_int(std::string_view key, int min, int max) {
    return static_cast<int>(integer(key, min, max));
}

double JsonReader::number(std::string_view key, Range range) {
    const json* value = find(key);
    return value == nullptr ? 0.0 : number_at(*value, path_of(key), range);
}

bool JsonReader::boolean(std::string_view key) {
    const json* value = find(key);
    return value != nullptr && boolean_at(*value, path_of(key));
}

std::string JsonReader::text(std::string_view key, std::size_t min_bytes, std::size_t max_bytes) {
    const json* value = find(key);
    return value == nullptr ? std::string() : text_at(*value, path_of(key), min_bytes, max_bytes);
}

const json* JsonReader::object(std::string_view key) {
    const json* value = find(key);
    if (value != nullptr && !value->is_object()) {
        wrong_type(*value, path_of(key), "an object", "must be an object");
        return nullptr;
    }
    return value;
}

const json* JsonReader::array(std::string_view key, std::size_t max_items) {
    const json* value = find(key);
    if (value == nullptr) {
        return nullptr;
    }
    if (!value->is_array()) {
        wrong_type(*value, path_of(key), "an array", "must be an array");
        return nullptr;
    }
    if (value->size() > max_items) {
        const std::string requirement = "must have at most " + std::to_string(max_items) + " items";
        reject(scene_code::kTooMany, path_of(key), requirement, path_of(key) + " " + requirement);
        return nullptr;
    }
    return value;
}

std::vector<int> JsonReader::int_array(std::string_view key, int min, int max,
                                       std::size_t max_items, bool exact) {
    std::vector<int> out;
    if (wording_ == Wording::Document) {
        const json* values = find(key);
        if (values != nullptr && (!values->is_array() || values->size() > max_items ||
                                  (exact && values->size() != max_items))) {
            fail(key,
                 "must be an array of " + std::string(exact ? "" : "at most ") +
                     std::to_string(max_items) + " integers",
                 scene_code::kWrongType);
        }
        for (std::size_t i = 0; ok() && i < values->size(); ++i) {
            out.push_back(
                static_cast<int>(integer_at((*values)[i], index_path(path_of(key), i), min, max)));
        }
        return out;
    }
    const json* values = array(key, max_items);
    if (values == nullptr) {
        return out;
    }
    out.reserve(values->size());
    for (const json& item : *values) {
        std::int64_t v = 0;
        if (!read_integer(item, min, max, v)) {
            fail(key, "must hold integers in " + integer_interval(min, max));
            return {};
        }
        out.push_back(static_cast<int>(v));
    }
    return out;
}

std::int64_t JsonReader::integer_at(const json& value, const std::string& path, std::int64_t min,
                                    std::int64_t max) {
    if (!ok()) {
        return 0;
    }
    const std::string requirement = "must be an integer in " + integer_interval(min, max);
    std::int64_t out = 0;
    if (!value.is_number_integer()) {
        wrong_type(value, path, "an integer", requirement);
    } else if (!read_integer(value, min, max, out)) {
        reject(scene_code::kOutOfRange, path, requirement, path + " " + requirement);
    }
    return ok() ? out : 0;
}

double JsonReader::number_at(const json& value, const std::string& path, Range range) {
    if (!ok()) {
        return 0.0;
    }
    const std::string wire_requirement =
        "must be a finite number in " +
        interval(wire_number(range.lo), wire_number(range.hi), range.lo_open);
    if (!value.is_number()) {
        wrong_type(value, path, "a number", wire_requirement);
        return 0.0;
    }
    const double v = value.get<double>();
    if (!std::isfinite(v)) {
        reject(scene_code::kNotFinite, path, wire_requirement, path + " must be a finite number");
    } else if (!range.contains(v)) {
        reject(scene_code::kOutOfRange, path, wire_requirement,
               path + " = " + document_number(v) + " is outside " +
                   interval(document_number(range.lo), document_number(range.hi), range.lo_open));
    }
    return ok() ? v : 0.0;
}

bool JsonReader::boolean_at(const json& value, const std::string& path) {
    if (!ok()) {
        return false;
    }
    if (!value.is_boolean()) {
        wrong_type(value, path, "true or false", "must be true or false");
        return false;
    }
    return value.get<bool>();
}

std::string JsonReader::text_at(const json& value, const std::string& path, std::size_t min_bytes,
                                std::size_t max_bytes) {
    if (!ok()) {
        return {};
    }
    const std::string* text = value.get_ptr<const std::string*>();
    if (text == nullptr) {
        wrong_type(value, path, "a string", "must be a string");
        return {};
    }
    if (text->size() < min_bytes || text->size() > max_bytes) {
        const std::string requirement =
            min_bytes == max_bytes ? "must be exactly " + std::to_string(min_bytes) + " bytes long"
                                   : "must be " + std::to_string(min_bytes) + " to " +
                                         std::to_string(max_bytes) + " bytes long";
        const std::string limit = text->size() > max_bytes
                                      ? "is longer than " + std::to_string(max_bytes)
                                      : "is shorter than " + std::to_string(min_bytes);
        reject(scene_code::kOutOfRange, path, requirement, path + " " + limit + " bytes");
        return {};
    }
    if (wording_ == Wording::Wire && has_control_character(*text)) {
        reject(scene_code::kBadValue, path, "must not contain control characters", {});
        return {};
    }
    return *text;
}

} // namespace carrom::proto::detail
