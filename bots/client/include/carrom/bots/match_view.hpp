#pragma once
// The rules' MatchState rebuilt from what a client is told (room_state), so that client-side
// strategies can reason with the rules engine. Four entries in room_state's seats make a doubles
// match (rules seat_count 4: seats bottom, right, top, left; teams 0+2 and 1+3); the scores and
// dues per team are the entries of seats 0 and 1. What room_state does not carry is inferred:
// the icf/discpool breaker is a seat playing white (the one to play before the break, else the
// first); the break counts as done once any piece left its starting spot; the pocketed list
// keeps the pieces without their shooters.

#include "carrom/proto/server_messages.hpp"
#include "carrom/rules/match_state.hpp"

namespace carrom::bots {

rules::MatchState match_state_from(const proto::RoomState& room, const PhysicsConfig& physics = {});

} // namespace carrom::bots
