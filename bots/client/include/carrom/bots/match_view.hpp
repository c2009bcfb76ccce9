#pragma once
// The rules' MatchState rebuilt from what a client is told (room_state), so that client-side
// strategies can reason with the rules engine. What room_state does not carry is inferred:
// the icf/discpool breaker is the seat playing white; the break counts as done once any piece
// left its starting spot; the pocketed list keeps the pieces without their shooters.

#include "carrom/proto/server_messages.hpp"
#include "carrom/rules/match_state.hpp"

namespace carrom::bots {

rules::MatchState match_state_from(const proto::RoomState& room, const PhysicsConfig& physics = {});

} // namespace carrom::bots
