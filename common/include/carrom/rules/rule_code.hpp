#pragma once
// Stable codes naming the rule behind a foul, a returned piece, or the end of a board or game.

#include "carrom/enum_names.hpp"

#include <cstdint>
#include <string_view>

namespace carrom::rules {

enum class RuleCode : std::uint8_t {
    StrikerPocketed,        // foul: the striker went into a pocket
    QueenBeforeOwnCoin,     // icf: queen pocketed before any own coin; it comes back
    QueenNotCovered,        // the cover stroke failed; the queen comes back
    QueenCovered,           // the queen was covered
    DuePaid,                // a coin came back to pay a due
    OwnLastCoinBeforeQueen, // icf: own last coin pocketed while the queen was not covered
    OpponentLastCoin,       // icf/discpool: the opponent's last coin was pocketed
    BreakMissed,            // icf: the break did not touch a coin; the breaker tries again
    ShotClockExpired,       // the shooter ran out of time; the turn passes
    MissedTurns,            // too many clock expiries in a row: the game is lost
    Forfeit,                // a seat gave up (or disconnected)
    BoardCleared,           // a side pocketed all its coins
    ColourCleared,          // seed: a colour is off the board
    CoinsExhausted,         // freestyle: no coins left on the board
    TargetPoints,           // a side reached the target score
    BoardsPlayed,           // icf: the board count was reached with a leader
};
inline constexpr enum_names::Table<RuleCode, 16> kRuleCodeNames{{
    {RuleCode::StrikerPocketed, "striker_pocketed"},
    {RuleCode::QueenBeforeOwnCoin, "queen_before_own_coin"},
    {RuleCode::QueenNotCovered, "queen_not_covered"},
    {RuleCode::QueenCovered, "queen_covered"},
    {RuleCode::DuePaid, "due_paid"},
    {RuleCode::OwnLastCoinBeforeQueen, "own_last_coin_before_queen"},
    {RuleCode::OpponentLastCoin, "opponent_last_coin"},
    {RuleCode::BreakMissed, "break_missed"},
    {RuleCode::ShotClockExpired, "shot_clock_expired"},
    {RuleCode::MissedTurns, "missed_turns"},
    {RuleCode::Forfeit, "forfeit"},
    {RuleCode::BoardCleared, "board_cleared"},
    {RuleCode::ColourCleared, "colour_cleared"},
    {RuleCode::CoinsExhausted, "coins_exhausted"},
    {RuleCode::TargetPoints, "target_points"},
    {RuleCode::BoardsPlayed, "boards_played"},
}};

// snake_case names: "striker_pocketed", "queen_before_own_coin", ...
std::string_view to_string(RuleCode code);
bool parse_rule_code(std::string_view text, RuleCode& out);

} // namespace carrom::rules
