#include "carrom/config.hpp"

#include <algorithm>
#include <cmath>

namespace carrom {

namespace {

std::optional<ConfigError> require(bool ok, const char* field, const char* message) {
    if (ok) {
        return std::nullopt;
    }
    return ConfigError{field, std::string(field) + " " + message};
}

bool positive(double v) {
    return std::isfinite(v) && v > 0.0;
}
bool non_negative(double v) {
    return std::isfinite(v) && v >= 0.0;
}
bool unit_interval(double v) {
    return std::isfinite(v) && v >= 0.0 && v <= 1.0;
}

} // namespace

std::optional<ConfigError> validate_config(const PhysicsConfig& c) {
    const std::optional<ConfigError> checks[] = {
        require(positive(c.board_size_px), "board_size_px", "must be a finite number > 0"),
        require(non_negative(c.frame_px), "frame_px", "must be a finite number >= 0"),
        require(positive(c.coin_radius_px), "coin_radius_px", "must be a finite number > 0"),
        require(positive(c.striker_radius_px), "striker_radius_px", "must be a finite number > 0"),
        require(positive(c.coin_mass), "coin_mass", "must be a finite number > 0"),
        require(positive(c.striker_mass), "striker_mass", "must be a finite number > 0"),
        require(non_negative(c.damping_per_s), "damping_per_s", "must be a finite number >= 0"),
        require(positive(c.stop_speed_px_s), "stop_speed_px_s", "must be a finite number > 0"),
        require(unit_interval(c.cushion_restitution), "cushion_restitution", "must be in [0, 1]"),
        require(unit_interval(c.disc_restitution), "disc_restitution", "must be in [0, 1]"),
        require(non_negative(c.restitution_floor_px_s), "restitution_floor_px_s",
                "must be a finite number >= 0"),
        require(positive(c.pocket_radius_px), "pocket_radius_px", "must be a finite number > 0"),
        require(positive(c.max_power), "max_power", "must be a finite number > 0"),
        require(positive(c.power_to_speed), "power_to_speed", "must be a finite number > 0"),
        require(non_negative(c.baseline_offset_px), "baseline_offset_px",
                "must be a finite number >= 0"),
        require(non_negative(c.baseline_end_margin_px), "baseline_end_margin_px",
                "must be a finite number >= 0"),
        require(c.max_events > 0, "max_events", "must be > 0"),
    };
    for (const auto& check : checks) {
        if (check) {
            return check;
        }
    }
    const double largest = std::max(c.coin_radius_px, c.striker_radius_px);
    if (c.cushion_max(largest) <= c.cushion_min(largest)) {
        return ConfigError{"frame_px", "frame_px and the radii leave no room inside the cushions"};
    }
    const double rs = c.striker_radius_px;
    if (c.baseline_offset_px < c.cushion_min(rs) || c.baseline_offset_px > c.cushion_max(rs)) {
        return ConfigError{"baseline_offset_px", "the baselines must lie inside the cushions"};
    }
    if (c.frame_px + c.baseline_end_margin_px + rs >= c.board_size_px / 2.0) {
        return ConfigError{"baseline_end_margin_px", "the baselines must have a usable length"};
    }
    return std::nullopt;
}

} // namespace carrom
