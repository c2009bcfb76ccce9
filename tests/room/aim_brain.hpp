#pragma once
// A bot brain for the room tests that plays from any of the four sides: a strong shot from a spot
// on its own baseline (spread by a fixed sequence) straight at a coin still on the board
// (deterministic, varied, and it pockets).

#include "carrom/room/bot_seat.hpp"
#include "carrom/rules/placement.hpp"

#include <cmath>
#include <cstdint>

namespace carrom::room::testing {

class AimBrain final : public BotBrain {
public:
    Shot choose_shot(const rules::MatchState& state, int seat, std::chrono::milliseconds) override {
        ++n_;
        const double spread = std::fmod(static_cast<double>(n_) * 0.61803398875, 1.0) - 0.5;
        const double along = 300.0 + 160.0 * spread;
        const auto side = state.seats[static_cast<std::size_t>(seat)].side;
        const Vec2 from = rules::striker_for(state.physics, side, Shot{along, 0.0, 0.0}).pos_px;
        Vec2 target = state.physics.centre();
        int coins = 0;
        for (const Body& body : state.bodies) {
            coins += body.pocketed ? 0 : 1;
        }
        int pick = coins > 0 ? static_cast<int>(n_ % coins) : 0;
        for (const Body& body : state.bodies) {
            if (!body.pocketed && pick-- == 0) {
                target = body.pos_px;
                break;
            }
        }
        return {along, std::atan2(target.y - from.y, target.x - from.x), 24.0};
    }

private:
    std::int64_t n_ = 0;
};

} // namespace carrom::room::testing
