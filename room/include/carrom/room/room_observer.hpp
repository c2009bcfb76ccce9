#pragma once
// What a room tells its owner about its members and games, for an operator: carrom-server logs
// each notice at info level (server/src/room_logger.cpp). Called on the room's thread, in the
// order things happen (a player who leaves a running game: Left, then the game's end). A room
// without an observer tells nobody.

#include "carrom/proto/server_messages.hpp"

#include <cstdint>
#include <string>

namespace carrom::room {

enum class MembershipChange : std::uint8_t {
    Joined,   // took a seat (a player or a bot) or came to watch
    Dropped,  // a seated player's connection ended; the seat waits for the grace period
    Returned, // a seated player resumed the seat
    Left,     // left the room, or the grace period ended: the seat is free again
};

struct MemberNotice {
    MembershipChange change = MembershipChange::Joined;
    std::string name;
    int seat = -1; // -1: a spectator
    bool bot = false;
};

class RoomObserver {
public:
    virtual ~RoomObserver() = default;
    virtual void member(const MemberNotice& notice) = 0;
    // The game ended: the game_end event the members were sent (winner seat or -1, reason,
    // scores per seat).
    virtual void game_over(const proto::GameEndEvent& end) = 0;
};

} // namespace carrom::room
