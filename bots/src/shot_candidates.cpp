#include "carrom/bots/shot_candidates.hpp"

#include "carrom/bots/position_value.hpp"
#include "carrom/bots/shot_geometry.hpp"
#include "carrom/rules/placement.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::bots {

namespace {

constexpr double kLegalSearchStepPx = 0.5;

std::optional<double> nearest_legal(const StrokeEvaluator& evaluator, double x_px,
                                    const BaselineRange& range) {
    const int steps = static_cast<int>((range.max_px - range.min_px) / kLegalSearchStepPx) + 1;
    for (int i = 0; i <= steps; ++i) {
        for (const double sign : {1.0, -1.0}) {
            const double x = x_px + sign * kLegalSearchStepPx * static_cast<double>(i);
            if (x >= range.min_px && x <= range.max_px && evaluator.placement_legal(x)) {
                return x;
            }
        }
    }
    return std::nullopt;
}

// Striker speed at contact (px/s) that sends a coin at rest off at the speed it needs to travel
// distance_px and still be moving: coin speed after a hit at cut angle c is
// (1 + e) m_s / (m_s + m_c) v cos c.
double contact_speed_px_s(const PhysicsConfig& physics, double distance_px, double cos_cut) {
    const double coin_speed = physics.damping_per_s * distance_px + physics.stop_speed_px_s;
    const double transfer = (1.0 + physics.disc_restitution) * physics.striker_mass /
                            (physics.striker_mass + physics.coin_mass);
    return coin_speed / (transfer * cos_cut);
}

} // namespace

std::vector<double> legal_baseline_xs(const StrokeEvaluator& evaluator, int count) {
    const BaselineRange range = baseline_range(evaluator.state());
    std::vector<double> xs;
    for (int i = 0; i < count; ++i) {
        const double t = count > 1 ? static_cast<double>(i) / static_cast<double>(count - 1) : 0.5;
        if (const auto x =
                nearest_legal(evaluator, range.min_px + t * (range.max_px - range.min_px), range)) {
            xs.push_back(*x);
        }
    }
    std::sort(xs.begin(), xs.end());
    xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
    return xs;
}

std::vector<Shot> grid_shots(const rules::MatchState& state, int seat, std::span<const double> xs,
                             const GridSpec& spec) {
    std::vector<Shot> shots;
    const double forward = forward_angle(state, seat);
    const int steps = std::max(spec.angle_steps, 1);
    for (const double x : xs) {
        for (int a = 0; a < steps; ++a) {
            const double t =
                steps > 1 ? static_cast<double>(a) / static_cast<double>(steps - 1) : 0.5;
            const double angle = forward - spec.spread_rad + 2.0 * spec.spread_rad * t;
            for (const double fraction : spec.power_fractions) {
                shots.push_back(Shot{x, angle, fraction * state.physics.max_power});
            }
        }
    }
    return shots;
}

std::vector<Shot> aimed_shots(const rules::MatchState& state, int seat, std::span<const double> xs,
                              const AimSpec& spec) {
    const PhysicsConfig& physics = state.physics;
    const rules::Side side = state.seats[static_cast<std::size_t>(seat)].side;
    const int team = rules::team_of(state, seat);
    const double forward = forward_angle(state, seat);
    const Vec2 ahead{std::cos(forward), std::sin(forward)};
    const double contact_px = physics.coin_radius_px + physics.striker_radius_px;
    const double lo = physics.cushion_min(physics.striker_radius_px);
    const double hi = physics.cushion_max(physics.striker_radius_px);
    const double max_speed = physics.max_power * physics.power_to_speed;
    std::vector<Shot> shots;
    for (const double x : xs) {
        const Vec2 striker = rules::striker_for(physics, side, Shot{x, 0.0, 0.0}).pos_px;
        for (const Body& coin : state.bodies) {
            if (!wants_to_pocket(state, team, coin)) {
                continue;
            }
            for (const Vec2& pocket : physics.pocket_centres()) {
                const Vec2 to_pocket = pocket - coin.pos_px;
                const double coin_travel_px = length(to_pocket);
                if (coin_travel_px <= 0.0) {
                    continue;
                }
                const Vec2 u = to_pocket * (1.0 / coin_travel_px);
                const Vec2 ghost = coin.pos_px - u * contact_px;
                if (ghost.x < lo || ghost.x > hi || ghost.y < lo || ghost.y > hi) {
                    continue; // the striker cannot get there
                }
                const Vec2 path = ghost - striker;
                const double path_px = length(path);
                if (path_px <= 0.0) {
                    continue;
                }
                const Vec2 dir = path * (1.0 / path_px);
                const double cos_cut = dot(dir, u);
                if (cos_cut < std::cos(spec.max_cut_rad) ||
                    dot(dir, ahead) < std::cos(spec.max_off_forward_rad)) {
                    continue;
                }
                const double angle = std::atan2(dir.y, dir.x);
                const double needed_px_s =
                    contact_speed_px_s(physics, coin_travel_px - physics.pocket_radius_px,
                                       cos_cut) +
                    physics.damping_per_s * path_px;
                for (const double factor : spec.power_factors) {
                    const double speed = std::min(factor * needed_px_s, max_speed);
                    shots.push_back(Shot{x, angle, speed / physics.power_to_speed});
                }
            }
        }
    }
    return shots;
}

} // namespace carrom::bots
