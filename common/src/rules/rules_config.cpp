#include "carrom/rules/rules_config.hpp"

#include <cmath>
#include <string>

namespace carrom::rules {
namespace {

RuleError invalid(std::string field, std::string message) {
    return RuleError{RuleErrorCode::InvalidConfig, std::move(field), std::move(message)};
}

std::optional<RuleError> check_int(const char* field, int value, int lo, int hi) {
    if (value < lo || value > hi) {
        return invalid(field, std::string(field) + " must be in [" + std::to_string(lo) + ", " +
                                  std::to_string(hi) + "], got " + std::to_string(value) + ".");
    }
    return std::nullopt;
}

std::optional<RuleError> check_seconds(const char* field, double value) {
    if (!std::isfinite(value) || value < 0.0 || value > 3600.0) {
        return invalid(field, std::string(field) + " must be a finite number of seconds in "
                                                   "[0, 3600].");
    }
    return std::nullopt;
}

} // namespace

std::optional<RuleError> validate_rules_config(const RulesConfig& c) {
    if (c.seat_count != 2 && c.seat_count != 4) {
        return invalid("seat_count", "seat_count must be 2 or 4.");
    }
    constexpr int kBig = 1000000;
    const std::optional<RuleError> checks[] = {
        check_int("first_breaker", c.first_breaker, 0, c.seat_count - 1),
        check_seconds("shot_clock_s", c.shot_clock_s),
        check_seconds("shot_clock_grace_s", c.shot_clock_grace_s),
        check_int("missed_turns_to_lose", c.missed_turns_to_lose, 1, 1000),
        check_int("target_points", c.target_points, 1, kBig),
        check_int("max_boards", c.max_boards, 1, 1000),
        check_int("queen_points", c.queen_points, 0, kBig),
        check_int("queen_points_limit", c.queen_points_limit, 0, kBig),
        check_int("board_points_cap", c.board_points_cap, 1, kBig),
        check_int("break_tries", c.break_tries, 1, 100),
        check_int("freestyle.white", c.freestyle.white, 0, kBig),
        check_int("freestyle.black", c.freestyle.black, 0, kBig),
        check_int("freestyle.queen", c.freestyle.queen, 0, kBig),
        check_int("freestyle.striker_penalty", c.freestyle.striker_penalty, 0, kBig),
        check_int("freestyle.target", c.freestyle.target, 1, kBig),
    };
    for (const auto& check : checks) {
        if (check) {
            return check;
        }
    }
    return std::nullopt;
}

} // namespace carrom::rules
