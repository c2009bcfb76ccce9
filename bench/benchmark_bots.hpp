#pragma once
// The bots' search benchmark set-up, shared by carrom_bench (bots_bench.cpp) and
// carrom-engine-runs --scene greedy, so that both measure the same decisions.

#include "carrom/bots/greedy_strategy.hpp"
#include "carrom/rules/match.hpp"

#include <chrono>

namespace carrom::bench {

// A new ICF match without a shot clock: the standard layout, seat 0 to break.
inline rules::MatchState standard_match() {
    rules::RulesConfig config;
    config.shot_clock_s = 0.0;
    return rules::new_match(rules::RuleSet::Icf, config, PhysicsConfig{});
}

// The hard greedy bot.
inline bots::GreedyOptions greedy_options() {
    bots::GreedyOptions options;
    options.level = bots::SkillLevel::Hard;
    return options;
}

// At most 2,000 candidates per decision and no practical time limit, so that every decision
// evaluates the same candidates whatever the machine's speed.
inline bots::DecisionBudget decision_budget() {
    bots::DecisionBudget budget;
    budget.time = std::chrono::seconds(60);
    budget.max_candidates = 2000;
    return budget;
}

} // namespace carrom::bench
