#include "carrom/rules/rule_error.hpp"

namespace carrom::rules {

std::string_view to_string(RuleErrorCode code) {
    switch (code) {
    case RuleErrorCode::InvalidSeat:
        return "invalid_seat";
    case RuleErrorCode::GameOver:
        return "game_over";
    case RuleErrorCode::BoardOver:
        return "board_over";
    case RuleErrorCode::NotYourTurn:
        return "not_your_turn";
    case RuleErrorCode::StaleTurn:
        return "stale_turn";
    case RuleErrorCode::XNotFinite:
        return "x_not_finite";
    case RuleErrorCode::XOutOfRange:
        return "x_out_of_range";
    case RuleErrorCode::StrikerOverlaps:
        return "striker_overlaps";
    case RuleErrorCode::AngleNotFinite:
        return "angle_not_finite";
    case RuleErrorCode::PowerNotFinite:
        return "power_not_finite";
    case RuleErrorCode::PowerOutOfRange:
        return "power_out_of_range";
    case RuleErrorCode::PhysicsError:
        return "physics_error";
    case RuleErrorCode::InvalidConfig:
        return "invalid_config";
    case RuleErrorCode::WrongPhase:
        return "wrong_phase";
    }
    return "unknown";
}

} // namespace carrom::rules
