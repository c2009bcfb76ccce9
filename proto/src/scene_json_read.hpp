#pragma once
// Field readers for the scene JSON decoders (internal). Each checks one value's type, finiteness
// and range and returns the first problem as a JsonError naming its path; none throws.

#include "carrom/proto/scene_json.hpp"
#include "carrom/vec2.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

namespace carrom::proto::scene_json_detail {

using Json = nlohmann::json;
using MaybeError = std::optional<JsonError>;

// The largest |score| (and points, dues, target) a match or journal file may hold.
inline constexpr int kMaxFileScore = 1000000;

std::string field_path(const std::string& parent, std::string_view name);
std::string index_path(const std::string& parent, std::size_t index);
JsonError make_error(std::string_view code, std::string path, std::string message);
std::string format_number(double value);
// "<path> must be <expected>, not <j's type>".
JsonError wrong_type(const std::string& path, const Json& j, std::string_view expected);

// j must be an object whose keys are all in allowed.
MaybeError check_object(const Json& j, const std::string& path,
                        std::initializer_list<std::string_view> allowed);
// j must be an object with this key.
MaybeError require_field(const Json& j, std::string_view key, const std::string& path);

// Inclusive range [lo, hi]; with lo_open, (lo, hi].
struct Range {
    double lo;
    double hi;
    bool lo_open = false;
    bool contains(double v) const { return (lo_open ? v > lo : v >= lo) && v <= hi; }
    std::string describe() const;
};

MaybeError read_number(const Json& j, const std::string& path, Range range, double& out);
MaybeError read_integer(const Json& j, const std::string& path, std::int64_t lo, std::int64_t hi,
                        std::int64_t& out);
MaybeError read_bool(const Json& j, const std::string& path, bool& out);
MaybeError read_string(const Json& j, const std::string& path, std::size_t max_bytes,
                       std::string& out);
// [x, y] or {"x": x, "y": y}, each component in [-limit, limit]; paths end in ".x" / ".y".
MaybeError read_vec(const Json& j, const std::string& path, double limit, Vec2& out);

} // namespace carrom::proto::scene_json_detail
