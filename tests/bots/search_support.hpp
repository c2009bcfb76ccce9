#pragma once
// What the strategy tests share: a search budget that only the candidate limit ends, and one
// shot played with the exact engine.

#include "carrom/bots/strategy.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"

#include <chrono>

namespace carrom::bots::test {

inline DecisionBudget candidates(int n) {
    DecisionBudget budget;
    budget.time = std::chrono::seconds(60); // the candidate limit ends the search
    budget.max_candidates = n;
    return budget;
}

inline rules::PlayResult play(const rules::MatchState& state, int seat, const Shot& shot) {
    ExactEngine engine(state.physics);
    return rules::play_shot(state, seat, shot, engine);
}

} // namespace carrom::bots::test
