#pragma once
// Where carrom-server's bot seats come from: a brain for a level (create_room with a bot, the
// quick-match fallback). An empty factory means the server has no bots ("unsupported").

#include "carrom/proto/types.hpp"
#include "carrom/room/bot_seat.hpp"

#include <functional>
#include <memory>

namespace carrom::server {

using BotFactory = std::function<std::shared_ptr<room::BotBrain>(proto::BotLevel level)>;

} // namespace carrom::server
