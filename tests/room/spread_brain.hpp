#pragma once
// A bot brain for the room tests: strong shots in directions spread by a fixed sequence
// (deterministic, varied, and they pocket).

#include "carrom/room/bot_seat.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace carrom::room::testing {

class SpreadBrain final : public BotBrain {
public:
    Shot choose_shot(const rules::MatchState& state, int, std::chrono::milliseconds) override {
        ++n_;
        const double up =
            state.seats[static_cast<std::size_t>(state.turn_seat)].side == rules::Side::Bottom
                ? -std::numbers::pi / 2.0
                : std::numbers::pi / 2.0;
        const double spread = std::fmod(static_cast<double>(n_) * 0.61803398875, 1.0) - 0.5;
        return {300.0 + 160.0 * spread, up + 1.1 * spread, 24.0};
    }

private:
    std::int64_t n_ = 0;
};

} // namespace carrom::room::testing
