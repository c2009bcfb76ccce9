#include "carrom/client/aim_gesture.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

std::vector<GestureStep> shot_gesture(const PhysicsConfig& physics, const AimConfig& aim,
                                      rules::Side side, double striker_along, const Shot& shot) {
    using Kind = GestureStep::Kind;
    std::vector<GestureStep> steps;
    const double lo = baseline_x_min(physics);
    const double hi = baseline_x_max(physics);
    const double x = clamp_baseline_x(physics, shot.x_px);
    // Slide: press on the baseline at the end away from the striker (a press on it would pull).
    const double far = striker_along > (lo + hi) / 2.0 ? lo : hi;
    steps.push_back({Kind::Press, baseline_point(physics, side, far)});
    steps.push_back({Kind::Move, baseline_point(physics, side, (far + x) / 2.0)});
    steps.push_back({Kind::Move, baseline_point(physics, side, x)});
    steps.push_back({Kind::Release, baseline_point(physics, side, x)});
    // Pull back from the striker: the shot goes from the pointer towards the striker.
    const double power = std::clamp(shot.power, 0.0, physics.max_power);
    const double drag =
        aim.dead_zone_px +
        std::max(power / physics.max_power * (aim.full_power_drag_px - aim.dead_zone_px), 1.0);
    const Vec2 dir{std::cos(shot.angle_rad), std::sin(shot.angle_rad)};
    const Vec2 striker = baseline_point(physics, side, x);
    steps.push_back({Kind::Press, striker});
    for (const double k : {0.25, 0.5, 0.75, 1.0}) {
        steps.push_back({Kind::Move, striker - dir * (drag * k)});
    }
    steps.push_back({Kind::Release, striker - dir * drag});
    return steps;
}

} // namespace carrom::client
