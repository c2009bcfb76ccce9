#include "carrom/rules/match_state.hpp"

namespace carrom::rules {

int team_of(const MatchState& state, int seat) {
    return team_of_seat(seat, state.config.seat_count);
}

std::optional<BodyKind> team_colour(const MatchState& state, int team) {
    switch (state.rule_set) {
    case RuleSet::Seed:
        return team == 0 ? BodyKind::Black : BodyKind::White;
    case RuleSet::Icf:
    case RuleSet::DiscPool:
        return team == team_of(state, state.breaker) ? BodyKind::White : BodyKind::Black;
    case RuleSet::Freestyle:
        break;
    }
    return std::nullopt;
}

int count_on_board(const MatchState& state, BodyKind kind) {
    int count = 0;
    for (const Body& body : state.bodies) {
        if (body.kind == kind && !body.pocketed) {
            ++count;
        }
    }
    return count;
}

} // namespace carrom::rules
