#include "carrom/client/demo_opponent.hpp"

#include "carrom/rules/placement.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {
namespace {

// The stroke from baseline position x towards target at the given power.
Shot towards(const rules::MatchState& state, int seat, double x, Vec2 target, double power) {
    const auto side = state.seats[static_cast<std::size_t>(seat)].side;
    const Vec2 from = rules::striker_for(state.physics, side, Shot{x, 0.0, 0.0}).pos_px;
    return {x, std::atan2(target.y - from.y, target.x - from.x), power};
}

Vec2 first_target(const rules::MatchState& state, int seat) {
    const auto colour = rules::team_colour(state, rules::team_of(state, seat));
    for (const Body& b : state.bodies) {
        if (!b.pocketed && b.kind != BodyKind::Queen && (!colour || b.kind == *colour)) {
            return b.pos_px;
        }
    }
    return state.physics.centre();
}

} // namespace

Shot DemoOpponent::choose_shot(const rules::MatchState& state, int seat,
                               std::chrono::milliseconds) {
    return shot_for(state, seat);
}

Shot DemoOpponent::shot_for(const rules::MatchState& state, int seat) {
    const PhysicsConfig& physics = state.physics;
    const double lo = baseline_x_min(physics);
    const double hi = baseline_x_max(physics);
    const bool breaking = state.strokes_this_board == 0;
    const Vec2 target = breaking ? physics.centre() : first_target(state, seat);
    const double power = breaking ? physics.max_power : 0.6 * physics.max_power;
    // In line with the target if that spot is free, else the nearest free spot, 1 px apart.
    const double start = std::clamp(target.x, lo, hi);
    const Shot first = towards(state, seat, start, target, power);
    if (!rules::check_placement(state, seat, first)) {
        return first;
    }
    for (double step = 1.0; step <= hi - lo; step += 1.0) {
        for (const double x : {start - step, start + step}) {
            if (x < lo || x > hi) {
                continue;
            }
            const Shot shot = towards(state, seat, x, target, power);
            if (!rules::check_placement(state, seat, shot)) {
                return shot;
            }
        }
    }
    return first; // the whole baseline is covered: refused, and the shot clock passes the turn
}

} // namespace carrom::client
