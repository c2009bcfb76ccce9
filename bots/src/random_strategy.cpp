#include "carrom/bots/random_strategy.hpp"

#include "carrom/bots/shot_geometry.hpp"

#include <numbers>

namespace carrom::bots {

namespace {
constexpr double kMaxSpreadRad = 75.0 * std::numbers::pi / 180.0; // either side of ahead
constexpr double kMinPowerFraction = 0.35;
constexpr int kPlacementTries = 32;
} // namespace

Shot RandomStrategy::draw(const rules::MatchState& state, int seat) {
    const BaselineRange range = baseline_range(state);
    std::uniform_real_distribution<double> x(range.min_px, range.max_px);
    std::uniform_real_distribution<double> spread(-kMaxSpreadRad, kMaxSpreadRad);
    std::uniform_real_distribution<double> power(kMinPowerFraction * state.physics.max_power,
                                                 state.physics.max_power);
    Shot shot;
    shot.x_px = x(rng_);
    shot.angle_rad = forward_angle(state, seat) + spread(rng_);
    shot.power = power(rng_);
    return shot;
}

Shot RandomStrategy::choose_shot(const rules::MatchState& state, int seat,
                                 const DecisionBudget& /*budget*/) {
    Shot shot = draw(state, seat);
    for (int i = 0; i < kPlacementTries && !shot_is_legal(state, seat, shot); ++i) {
        shot.x_px = draw(state, seat).x_px;
    }
    if (!shot_is_legal(state, seat, shot)) {
        shot.x_px = nearest_legal_x(state, seat, shot.x_px).value_or(shot.x_px);
    }
    return shot;
}

} // namespace carrom::bots
