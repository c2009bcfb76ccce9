#pragma once
// "sampling": draws random legal shots (as "random" does), simulates each with the exact engine
// and the rules, and plays the one whose outcome scores best (shot_score.hpp). Stops at the
// budget's time or candidate limit, or after `candidates` shots. A cheap stand-in for the
// search strategies of issue 7 that makes test matches end in few strokes. Deterministic for a
// seed when the candidate limit (not the clock) ends the search.

#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/shot_score.hpp"
#include "carrom/bots/strategy.hpp"

namespace carrom::bots {

class SamplingStrategy final : public Strategy {
public:
    SamplingStrategy(std::uint64_t seed, int candidates);
    std::string_view name() const override { return "sampling"; }
    Shot choose_shot(const rules::MatchState& state, int seat,
                     const DecisionBudget& budget) override;
    int last_candidates() const { return last_candidates_; } // simulated in the last decision

private:
    RandomStrategy random_;
    int candidates_;
    int last_candidates_ = 0;
};

} // namespace carrom::bots
