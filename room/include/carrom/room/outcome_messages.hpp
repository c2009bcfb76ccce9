#pragma once
// Translation between the rules engine's types and the wire's.

#include "carrom/proto/error.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/rules/match.hpp"

#include <string_view>
#include <vector>

namespace carrom::room {

proto::QueenInfo to_proto(const rules::QueenState& queen);
proto::Colour colour_of_team(const rules::MatchState& state, int team);
// One plain sentence per rule code (foul messages).
std::string_view rule_sentence(rules::RuleCode code);
// A foul's sentence for its seat: the rule's sentence, and after a missed shot clock how many
// more misses in a row lose the game ("The shot clock ran out; the turn passes. 2 more missed
// turns in a row lose the game.").
std::string foul_sentence(const rules::Foul& foul, const rules::MatchState& after);
// "score", "boards", "cleared", "forfeit", "clock".
std::string_view game_end_reason(rules::RuleCode code);
// A refused input: the rules' error (check_turn, check_placement, play_shot) as the wire's code,
// with the rules' sentence.
proto::Error to_proto_error(const rules::RuleError& error);

// Per-seat view of per-team numbers (singles: identical; doubles: partners share).
std::vector<int> per_seat(const rules::MatchState& state, const std::vector<int>& per_team);

proto::ShotResult to_shot_result(const rules::ShotOutcome& outcome, const rules::MatchState& after);
// foul, queen (if it changed), due (if a team's dues changed), board_end, game_end.
std::vector<proto::Event> rule_events(const rules::ShotOutcome& outcome,
                                      const rules::MatchState& before,
                                      const rules::MatchState& after);

} // namespace carrom::room
