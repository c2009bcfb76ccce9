#include "scene_json_read.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace carrom::proto::scene_json_detail {

std::string field_path(const std::string& parent, std::string_view name) {
    return parent.empty() ? std::string(name) : parent + "." + std::string(name);
}

std::string index_path(const std::string& parent, std::size_t index) {
    return parent + "[" + std::to_string(index) + "]";
}

JsonError make_error(std::string_view code, std::string path, std::string message) {
    return JsonError{std::string(code), std::move(path), std::move(message)};
}

std::string format_number(double value) {
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end);
}

std::string Range::describe() const {
    return std::string(lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + "]";
}

namespace {

std::string name_of(const std::string& path) {
    return path.empty() ? "the document" : path;
}

const char* type_name(const Json& j) {
    return j.is_number() ? "a number" : j.type_name(); // type_name: "string", "object", ...
}

} // namespace

JsonError wrong_type(const std::string& path, const Json& j, std::string_view expected) {
    return make_error(scene_code::kWrongType, path,
                      name_of(path) + " must be " + std::string(expected) + ", not " +
                          type_name(j));
}

MaybeError check_object(const Json& j, const std::string& path,
                        std::initializer_list<std::string_view> allowed) {
    if (!j.is_object()) {
        return wrong_type(path, j, "an object");
    }
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            return make_error(scene_code::kUnknownField, field_path(path, key),
                              "unknown field '" + key + "' in " + name_of(path));
        }
    }
    return std::nullopt;
}

MaybeError require_field(const Json& j, std::string_view key, const std::string& path) {
    if (j.contains(key)) {
        return std::nullopt;
    }
    return make_error(scene_code::kMissingField, field_path(path, key),
                      name_of(path) + " needs the field '" + std::string(key) + "'");
}

MaybeError read_number(const Json& j, const std::string& path, Range range, double& out) {
    if (!j.is_number()) {
        return wrong_type(path, j, "a number");
    }
    const double v = j.get<double>();
    if (!std::isfinite(v)) {
        return make_error(scene_code::kNotFinite, path, path + " must be a finite number");
    }
    if (!range.contains(v)) {
        return make_error(scene_code::kOutOfRange, path,
                          path + " = " + format_number(v) + " is outside " + range.describe());
    }
    out = v;
    return std::nullopt;
}

MaybeError read_integer(const Json& j, const std::string& path, std::int64_t lo, std::int64_t hi,
                        std::int64_t& out) {
    if (!j.is_number_integer()) {
        return wrong_type(path, j, "an integer");
    }
    const bool too_big = j.is_number_unsigned() &&
                         j.get<std::uint64_t>() >
                             static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
    const std::int64_t v =
        too_big ? std::numeric_limits<std::int64_t>::max() : j.get<std::int64_t>();
    if (too_big || v < lo || v > hi) {
        return make_error(scene_code::kOutOfRange, path,
                          path + " must be an integer in [" + std::to_string(lo) + ", " +
                              std::to_string(hi) + "]");
    }
    out = v;
    return std::nullopt;
}

MaybeError read_bool(const Json& j, const std::string& path, bool& out) {
    if (!j.is_boolean()) {
        return wrong_type(path, j, "true or false");
    }
    out = j.get<bool>();
    return std::nullopt;
}

MaybeError read_string(const Json& j, const std::string& path, std::size_t max_bytes,
                       std::string& out) {
    if (!j.is_string()) {
        return wrong_type(path, j, "a string");
    }
    const auto& s = j.get_ref<const std::string&>();
    if (s.size() > max_bytes) {
        return make_error(scene_code::kOutOfRange, path,
                          path + " is longer than " + std::to_string(max_bytes) + " bytes");
    }
    out = s;
    return std::nullopt;
}

MaybeError read_vec(const Json& j, const std::string& path, double limit, Vec2& out) {
    const Range range{-limit, limit};
    if (j.is_array()) {
        if (j.size() != 2) {
            return make_error(scene_code::kWrongType, path,
                              path + " must be [x, y], not an array of " +
                                  std::to_string(j.size()));
        }
        if (auto e = read_number(j[0], field_path(path, "x"), range, out.x)) {
            return e;
        }
        return read_number(j[1], field_path(path, "y"), range, out.y);
    }
    if (j.is_object()) {
        if (auto e = check_object(j, path, {"x", "y"})) {
            return e;
        }
        for (std::string_view axis : {"x", "y"}) {
            if (auto e = require_field(j, axis, path)) {
                return e;
            }
        }
        if (auto e = read_number(j["x"], field_path(path, "x"), range, out.x)) {
            return e;
        }
        return read_number(j["y"], field_path(path, "y"), range, out.y);
    }
    return wrong_type(path, j, "[x, y]");
}

} // namespace carrom::proto::scene_json_detail
