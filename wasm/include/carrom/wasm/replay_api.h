#pragma once
// The C API's replay half (engine_api.h has the conventions): a match journal's inputs played
// through the rules and the exact engine as the server played them (proto/journal_replay.hpp,
// "Replay"), one input at a time, for the page's replays (web/js/replay_model.js). The page
// decodes the journal's JSON itself and hands over numbers.

#include <cstdint>

extern "C" {

// kRulesVersion (carrom/rules/rules_version.hpp).
int carrom_rules_version();

// The rules config, 16 doubles written by the caller before carrom_replay_start, in this order:
// seat_count, first_breaker, shot_clock_s, shot_clock_grace_s, missed_turns_to_lose,
// target_points, max_boards, queen_points, queen_points_limit, board_points_cap, break_tries,
// freestyle.white, freestyle.black, freestyle.queen, freestyle.striker_penalty, freestyle.target.
double* carrom_replay_config();

// A new game: new_match(rule_set (0 icf, 1 seed, 2 freestyle, 3 discpool), config, the default
// physics) with turn_number = first_turn. Returns 0, or -1 (carrom_error: "invalid_config").
int carrom_replay_start(int rule_set, int first_turn);

// Plays one input on the current state: kind 0 a stroke (seat, shot), 1 a shot clock expiry,
// 2 a forfeit (seat); a state whose board is over then goes on with start_next_board, as the
// server does. Returns 0, or -1 when the rules refuse it (carrom_error: the rule's code; nothing
// changes). To animate a stroke the page simulates it with carrom_simulate from the board it was
// played on (carrom_replay_board before the call) and the seat's side: play_shot places the
// striker and orders the bodies the same way, so the trajectory is the one the rules judged.
int carrom_replay_play(int kind, int seat, double x_px, double angle_rad, double power);

// The state the last input left, as the rules returned it (before start_next_board), 24 doubles:
// turn_number, turn_seat, board, phase (0 awaiting a shot, 1 board over, 2 game over), then per
// team (4 slots, unused ones 0) the scores and the dues owed, then the game's winner team (-1 a
// draw, -2 no result), its reason (rules::RuleCode as a number, -1 none), the last board
// result's winner team (-1 none or a draw), its points, and the state hash
// (rules::hash_match_state) as two 32-bit halves, then the side (0..3) of seats 0..3 (-1 none).
const double* carrom_replay_result();

// A board of 19 body records (5 doubles each, carrom_scene's form): next = 0 the board as the
// rules returned it after the last input (returned pieces placed), next = 1 the board the next
// input is played on (after start_next_board; the first board after carrom_replay_start).
const double* carrom_replay_board(int next);

} // extern "C"
