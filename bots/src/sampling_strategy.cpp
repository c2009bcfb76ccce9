#include "carrom/bots/sampling_strategy.hpp"

#include "carrom/bots/shot_geometry.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"

#include <chrono>
#include <limits>

namespace carrom::bots {

SamplingStrategy::SamplingStrategy(std::uint64_t seed, int candidates)
    : random_(seed), candidates_(candidates < 1 ? 1 : candidates) {}

Shot SamplingStrategy::choose_shot(const rules::MatchState& state, int seat,
                                   const DecisionBudget& budget) {
    ExactEngine engine(state.physics); // cheap next to the candidates it simulates
    const auto deadline = std::chrono::steady_clock::now() + budget.time;
    const int limit = std::min(candidates_, budget.max_candidates);
    Shot best = random_.choose_shot(state, seat, budget);
    double best_score = -std::numeric_limits<double>::infinity();
    last_candidates_ = 0;
    for (int i = 0; i < limit; ++i) {
        const Shot shot = i == 0 ? best : random_.choose_shot(state, seat, budget);
        const rules::PlayResult result = rules::play_shot(state, seat, shot, engine);
        ++last_candidates_;
        if (!result.error) {
            const double score = score_outcome(state, result, seat);
            if (score > best_score) {
                best_score = score;
                best = shot;
            }
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            break;
        }
    }
    return best;
}

} // namespace carrom::bots
