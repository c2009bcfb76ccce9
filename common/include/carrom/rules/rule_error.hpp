#pragma once
// Why the rules refused something (a stroke, a placement, a config, an action). Plain data: a
// code to act on, the offending field and one plain sentence for people.

#include "carrom/enum_names.hpp"

#include <cstdint>
#include <string>
#include <string_view>

namespace carrom::rules {

enum class RuleErrorCode : std::uint8_t {
    InvalidSeat,     // no such seat
    GameOver,        // the game has ended
    BoardOver,       // the board has ended and the next one has not started
    NotYourTurn,     // another seat is to play
    StaleTurn,       // the input names a turn number other than the current one
    XNotFinite,      // striker position
    XOutOfRange,     //   off the baseline
    StrikerOverlaps, //   on a piece
    AngleNotFinite,  // stroke
    PowerNotFinite,  //
    PowerOutOfRange, //
    PhysicsError,    // the engine refused the scene
    InvalidConfig,   // a RulesConfig value out of range
    WrongPhase,      // an action the current phase does not allow
};
inline constexpr enum_names::Table<RuleErrorCode, 14> kRuleErrorCodeNames{{
    {RuleErrorCode::InvalidSeat, "invalid_seat"},
    {RuleErrorCode::GameOver, "game_over"},
    {RuleErrorCode::BoardOver, "board_over"},
    {RuleErrorCode::NotYourTurn, "not_your_turn"},
    {RuleErrorCode::StaleTurn, "stale_turn"},
    {RuleErrorCode::XNotFinite, "x_not_finite"},
    {RuleErrorCode::XOutOfRange, "x_out_of_range"},
    {RuleErrorCode::StrikerOverlaps, "striker_overlaps"},
    {RuleErrorCode::AngleNotFinite, "angle_not_finite"},
    {RuleErrorCode::PowerNotFinite, "power_not_finite"},
    {RuleErrorCode::PowerOutOfRange, "power_out_of_range"},
    {RuleErrorCode::PhysicsError, "physics_error"},
    {RuleErrorCode::InvalidConfig, "invalid_config"},
    {RuleErrorCode::WrongPhase, "wrong_phase"},
}};

// snake_case names, stable (printed by carrom-sim --rules): "invalid_seat", "game_over", ...
std::string_view to_string(RuleErrorCode code);

struct RuleError {
    RuleErrorCode code = RuleErrorCode::InvalidSeat;
    std::string field;   // the offending field ("shot.x", "seat", ...), empty if none
    std::string message; // one plain sentence
};

} // namespace carrom::rules
