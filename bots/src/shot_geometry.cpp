#include "carrom/bots/shot_geometry.hpp"

#include "carrom/rules/placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carrom::bots {

BaselineRange baseline_range(const rules::MatchState& state) {
    return {baseline_x_min(state.physics), baseline_x_max(state.physics)};
}

bool shot_is_legal(const rules::MatchState& state, int seat, const Shot& shot) {
    return !rules::check_placement(state, seat, shot).has_value();
}

std::optional<double> nearest_legal_x(const rules::MatchState& state, int seat, double x_px) {
    const BaselineRange range = baseline_range(state);
    const double start =
        std::clamp(std::isfinite(x_px) ? x_px : range.min_px, range.min_px, range.max_px);
    constexpr double kStepPx = 0.5;
    const int steps = static_cast<int>((range.max_px - range.min_px) / kStepPx) + 1;
    for (int i = 0; i <= steps; ++i) {
        for (const double sign : {1.0, -1.0}) {
            const double x = start + sign * kStepPx * static_cast<double>(i);
            if (x < range.min_px || x > range.max_px) {
                continue;
            }
            if (shot_is_legal(state, seat, Shot{x, forward_angle(state, seat), 0.0})) {
                return x;
            }
        }
    }
    return std::nullopt;
}

double forward_angle(const rules::MatchState& state, int seat) {
    rules::Side side = rules::Side::Bottom;
    if (seat >= 0 && static_cast<std::size_t>(seat) < state.seats.size()) {
        side = state.seats[static_cast<std::size_t>(seat)].side;
    }
    switch (side) {
    case rules::Side::Bottom:
        return -std::numbers::pi / 2.0;
    case rules::Side::Top:
        return std::numbers::pi / 2.0;
    case rules::Side::Right:
        return std::numbers::pi;
    case rules::Side::Left:
        return 0.0;
    }
    return -std::numbers::pi / 2.0;
}

} // namespace carrom::bots
