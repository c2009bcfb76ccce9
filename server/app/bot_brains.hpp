#pragma once
// Server-side bot seats for carrom-server: a BotFactory whose brains are the strategies of
// bots/ (carrom_bots). Level "random" plays random legal shots; "easy", "medium" and "hard"
// are the greedy search strategy with that level's execution noise (docs/bots.md), each
// decision within think_ms of wall time.

#include "carrom/server/bot_factory.hpp"

#include <chrono>
#include <cstdint>

namespace carrom::server {

BotFactory
make_strategy_bot_factory(std::uint64_t seed,
                          std::chrono::milliseconds think = std::chrono::milliseconds(300));

} // namespace carrom::server
