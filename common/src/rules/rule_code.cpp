#include "carrom/rules/rule_code.hpp"

#include <array>
#include <utility>

namespace carrom::rules {
namespace {

constexpr std::array<std::pair<RuleCode, std::string_view>, 16> kRuleCodeNames{{
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

} // namespace

std::string_view to_string(RuleCode code) {
    for (const auto& [value, name] : kRuleCodeNames) {
        if (value == code) {
            return name;
        }
    }
    return "unknown";
}

bool parse_rule_code(std::string_view text, RuleCode& out) {
    for (const auto& [value, name] : kRuleCodeNames) {
        if (name == text) {
            out = value;
            return true;
        }
    }
    return false;
}

} // namespace carrom::rules
