#pragma once
// JSON for the rules engine: match state (both ways), rules config (both ways) and shot outcome
// (encode). Used by `carrom-sim --rules` (docs/rules.md) and available to the server. Decoding
// never throws: every decoder returns a value or an Error naming the offending value's path
// ("state.queen.seat", "state.bodies[3].pos.x"), a stable code and one sentence.

#include "carrom/enum_names.hpp"
#include "carrom/proto/scene_json.hpp"
#include "carrom/rules/match.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace carrom::proto {

namespace match_code {
// Besides the scene_code::* codes: the state's fields contradict each other (a pocketed body
// that is not in the pocketed list, a queen status that does not match the queen body, ...).
inline constexpr std::string_view kInconsistentState = "inconsistent_state";
} // namespace match_code

// The largest |score| (and points, dues, target) a match or journal file may hold.
inline constexpr int kMaxFileScore = 1000000;

// Every field of the config.
nlohmann::json rules_config_to_json(const rules::RulesConfig& config);
// Applies the overrides in j (an object; every field optional, unknown keys rejected) to base,
// then runs validate_rules_config.
Decoded<rules::RulesConfig> decode_rules_config(const nlohmann::json& j,
                                                const rules::RulesConfig& base = {},
                                                const std::string& path = "rules");

// Every field of the state: {"rule_set", "rules", "physics" (overrides only), "seats",
// "bodies", "pocketed", "scores", "dues_owed", "missed_turns", "board", "breaker", "turn_seat",
// "turn_number", "strokes_this_board", "break_tries", "break_done", "queen", "phase", "boards",
// "result"}. Round-trips exactly through decode_match_state.
nlohmann::json match_state_to_json(const rules::MatchState& state);
// Only "rule_set" is required (default "icf" when absent too); every other field defaults to
// that of new_match(rule_set, rules, physics). "seats" is derived from rules.seat_count and is
// ignored on input. Checks types, ranges and the consistency of the fields with each other.
Decoded<rules::MatchState> decode_match_state(const nlohmann::json& j,
                                              const std::string& path = "state");

nlohmann::json queen_state_to_json(const rules::QueenState& queen);
nlohmann::json board_result_to_json(const rules::BoardResult& board);
nlohmann::json game_result_to_json(const rules::GameResult& result);
// The inverses, for a match of `teams` teams (winner_team null or in [0, teams)).
Decoded<rules::BoardResult> decode_board_result(const nlohmann::json& j, int teams,
                                                const std::string& path);
Decoded<rules::GameResult> decode_game_result(const nlohmann::json& j, int teams,
                                              const std::string& path);
// {"x", "angle", "power"}.
nlohmann::json rules_shot_to_json(const Shot& shot);
// {"x", "angle", "power"}: finite numbers (placement is the rules' job: check_placement).
Decoded<Shot> decode_rules_shot(const nlohmann::json& j, const std::string& path = "shot");

// The outcome; "physics" (sim_result_to_json) only when include_physics.
nlohmann::json shot_outcome_to_json(const rules::ShotOutcome& outcome, bool include_physics);

// snake_case names of the state's enums (the rules engine's Phase, not the wire's proto::Phase).
inline constexpr enum_names::Table<rules::Phase, 3> kMatchPhaseNames{{
    {rules::Phase::AwaitingShot, "awaiting_shot"},
    {rules::Phase::BoardOver, "board_over"},
    {rules::Phase::GameOver, "game_over"},
}};
inline constexpr enum_names::Table<rules::QueenStatus, 4> kQueenStatusNames{{
    {rules::QueenStatus::OnBoard, "on_board"},
    {rules::QueenStatus::PendingCover, "pending_cover"},
    {rules::QueenStatus::Covered, "covered"},
    {rules::QueenStatus::OutOfPlay, "out_of_play"},
}};
std::string_view to_string(rules::Phase phase);
bool parse_phase(std::string_view text, rules::Phase& out);
std::string_view to_string(rules::QueenStatus status);
bool parse_queen_status(std::string_view text, rules::QueenStatus& out);

} // namespace carrom::proto
