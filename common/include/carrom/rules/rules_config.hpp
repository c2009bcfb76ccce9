#pragma once
// Every number the rules use, in one plain struct. Defaults follow the ICF laws
// (../shared/reference/carrom-rules.md) and, for Freestyle, what popular apps use.

#include "carrom/rules/rule_error.hpp"

#include <optional>

namespace carrom::rules {

// Freestyle points. Scores may go below zero.
struct FreestylePoints {
    int white = 20;
    int black = 10;
    int queen = 50;           // awarded when the queen is covered
    int striker_penalty = 20; // subtracted when the shooter pockets the striker
    int target = 170;         // first side to reach this wins
    friend bool operator==(const FreestylePoints&, const FreestylePoints&) = default;
};

struct RulesConfig {
    int seat_count = 2;              // 2 (singles) or 4 (doubles: partners opposite)
    int first_breaker = 0;           // seat that breaks board 1 (the toss is the caller's)
    double shot_clock_s = 20.0;      // time per stroke, s; 0 turns the clock off
    double shot_clock_grace_s = 0.5; // latency allowance added by shot_clock_ran_out, s
    int missed_turns_to_lose = 3;    // clock expiries in a row by one seat that lose the game
    // icf
    int target_points = 25;      // a game ends when a side reaches this (after a board)
    int max_boards = 8;          // ... or after this many boards unless tied (then tie-breaks)
    int queen_points = 3;        // icf board bonus for covering; seed cover bonus; icf
                                 // own-last-coin penalty
    int queen_points_limit = 22; // icf: no queen points for a side with at least this many
    int board_points_cap = 12;   // icf: most points one board can give
    int break_tries = 3;         // icf: tries to touch a coin on the break
    FreestylePoints freestyle{}; //
    friend bool operator==(const RulesConfig&, const RulesConfig&) = default;
};

// Checks every field; returns the first problem (code "invalid_config", field named).
std::optional<RuleError> validate_rules_config(const RulesConfig& config);

} // namespace carrom::rules
