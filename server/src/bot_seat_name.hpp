#pragma once
// The names the server gives its bot seats, and a bot's level read back from such a name (the
// journal keeps only names: a match recovered after a restart gets brains of the same level).
//
// Singles: "Bot (hard)". Doubles: each bot seat its own first name, "Bot Ravi (easy)", so that
// three bots at one table are told apart. The level is the word in the last parentheses.

#include "carrom/proto/types.hpp"

#include <string>
#include <string_view>

namespace carrom::server {

// The name of a server bot of `level` in `seat` (0-based) of a room of `seats` seats.
std::string bot_seat_name(proto::BotLevel level, int seat, int seats);

// The level in a name bot_seat_name gives; medium for any other name.
proto::BotLevel bot_level_of_name(std::string_view name);

} // namespace carrom::server
