#pragma once
// The offline demo's opponent: a bot seat brain that plays plain, legal strokes at once. The
// break goes straight at the centre at full power; later strokes aim at the first coin of the
// seat's colour (any coin while colours are open) at 60 % power, from the free spot on the
// baseline nearest in line with it. Every stroke it returns passes rules::check_placement when
// one exists. Stateless, so any seat may ask (the demo's autoplay uses it for the player).

#include "carrom/room/bot_seat.hpp"

namespace carrom::client {

class DemoOpponent final : public room::BotBrain {
public:
    Shot choose_shot(const rules::MatchState& state, int seat,
                     std::chrono::milliseconds waited) override;

    static Shot shot_for(const rules::MatchState& state, int seat);
};

} // namespace carrom::client
