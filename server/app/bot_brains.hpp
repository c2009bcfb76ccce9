#pragma once
// Server-side bot seats for carrom-server: a BotFactory whose brains are the strategies of
// bots/ (carrom_bots_lib). Level "random" plays random legal shots; "easy", "medium" and "hard"
// use the sampling strategy with more candidate shots per decision.

#include "carrom/server/bot_seat.hpp"

#include <cstdint>

namespace carrom::server {

BotFactory make_strategy_bot_factory(std::uint64_t seed);

} // namespace carrom::server
