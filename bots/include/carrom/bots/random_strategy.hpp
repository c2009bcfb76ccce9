#pragma once
// "random": a legal striker position chosen uniformly on the baseline, a direction within 75
// degrees of straight ahead, power uniform in [35%, 100%] of the maximum. Deterministic for a
// seed.

#include "carrom/bots/strategy.hpp"

#include <random>

namespace carrom::bots {

class RandomStrategy final : public Strategy {
public:
    explicit RandomStrategy(std::uint64_t seed) : rng_(seed) {}
    std::string_view name() const override { return "random"; }
    Shot choose_shot(const rules::MatchState& state, int seat,
                     const DecisionBudget& budget) override;

    // One random shot (placement not checked): what choose_shot draws before making it legal.
    Shot draw(const rules::MatchState& state, int seat);

private:
    std::mt19937_64 rng_;
};

} // namespace carrom::bots
