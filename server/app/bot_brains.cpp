#include "bot_brains.hpp"

#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/sampling_strategy.hpp"

#include <atomic>
#include <mutex>

namespace carrom::server {

namespace {

// Candidate shots the sampling strategy simulates per decision, by level.
int candidates_for(proto::BotLevel level) {
    switch (level) {
    case proto::BotLevel::Easy:
        return 8;
    case proto::BotLevel::Medium:
        return 64;
    case proto::BotLevel::Hard:
        return 512;
    case proto::BotLevel::Random:
        return 0;
    }
    return 0;
}

// A strategy behind a mutex: the server may call a brain from any worker thread, one at a time.
class StrategyBrain final : public BotBrain {
public:
    explicit StrategyBrain(std::unique_ptr<bots::Strategy> strategy)
        : strategy_(std::move(strategy)) {}

    Shot choose_shot(const rules::MatchState& state, int seat) override {
        const std::lock_guard lock(mutex_);
        return strategy_->choose_shot(state, seat, bots::DecisionBudget{});
    }

private:
    std::mutex mutex_;
    std::unique_ptr<bots::Strategy> strategy_;
};

} // namespace

BotFactory make_strategy_bot_factory(std::uint64_t seed) {
    auto next_seed = std::make_shared<std::atomic<std::uint64_t>>(seed);
    return [next_seed](proto::BotLevel level) -> std::shared_ptr<BotBrain> {
        const std::uint64_t bot_seed = next_seed->fetch_add(1);
        const int candidates = candidates_for(level);
        std::unique_ptr<bots::Strategy> strategy;
        if (candidates == 0) {
            strategy = std::make_unique<bots::RandomStrategy>(bot_seed);
        } else {
            strategy = std::make_unique<bots::SamplingStrategy>(bot_seed, candidates);
        }
        return std::make_shared<StrategyBrain>(std::move(strategy));
    };
}

} // namespace carrom::server
