#pragma once
// The seam for bot seats. A room can seat a BotBrain; when it is the bot's turn the room hands out
// a BotTurn once (Room::take_bot_turn); its driver runs choose_shot and gives the shot back
// (Room::bot_shoot). carrom-server runs brains on a worker thread, never on an I/O thread, and
// posts the result back to the room's strand; the client's offline demo calls its opponent on
// the UI thread. A brain must be callable from any single thread at a time.

#include "carrom/proto/error.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/scene.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>

namespace carrom::room {

class BotBrain {
public:
    virtual ~BotBrain() = default;
    // May take a while (a time budget); must not touch the room. waited: how long the turn
    // waited for a free bot worker before this call, to be taken off the brain's budget so
    // that the answer comes within the budget of the turn being handed out.
    virtual Shot choose_shot(const rules::MatchState& state, int seat,
                             std::chrono::milliseconds waited) = 0;
};

struct BotTurn {
    int seat = 0;
    int turn = 0;
    rules::MatchState state;
    std::shared_ptr<BotBrain> brain;
};

// What Room::bot_shoot did with a brain's shot. A shot the rules refuse for its numbers or its
// place (off the baseline, on a piece, not finite, power out of range) is played as the nearest
// legal one (rules::nearest_legal_shot): a brain's mistake must not stall the match, and with
// the shot clock off nothing else would end the turn.
struct BotShotOutcome {
    std::optional<proto::Error> refused;  // nothing was played: no bot there, not its turn
    std::optional<proto::Error> replaced; // played as the nearest legal shot: why the brain's
                                          // own was refused
};

} // namespace carrom::room
