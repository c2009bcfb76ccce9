#pragma once
// The seam for server-side bot seats (issue 7). A room can seat a BotBrain; when it is the bot's
// turn the room hands out a BotTurn once (Room::take_bot_turn); the network layer runs
// choose_shot on a worker thread, never on an I/O thread, and posts the result back to the room's
// strand (Room::bot_shoot). A brain must be callable from any single thread at a time.

#include "carrom/proto/types.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/scene.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <string>

namespace carrom::server {

class BotBrain {
public:
    virtual ~BotBrain() = default;
    // May take a while (a time budget); must not touch the room. waited: how long the turn
    // waited for a free bot worker before this call, to be taken off the brain's budget so
    // that the answer comes within the budget of the turn being handed out.
    virtual Shot choose_shot(const rules::MatchState& state, int seat,
                             std::chrono::milliseconds waited) = 0;
};

// Makes a brain for a level; an empty factory means the server has no bots ("unsupported").
using BotFactory = std::function<std::shared_ptr<BotBrain>(proto::BotLevel level)>;

struct BotTurn {
    int seat = 0;
    int turn = 0;
    rules::MatchState state;
    std::shared_ptr<BotBrain> brain;
};

} // namespace carrom::server
