#include "bot_brains.hpp"

#include "carrom/bots/greedy_strategy.hpp"
#include "carrom/bots/random_strategy.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <mutex>

namespace carrom::server {

namespace {

// A bot that queued longer than its budget still thinks this long (its first candidates).
constexpr std::chrono::milliseconds kLeastThink{10};

// A strategy behind a mutex: the server may call a brain from any worker thread, one at a time.
class StrategyBrain final : public room::BotBrain {
public:
    StrategyBrain(std::unique_ptr<bots::Strategy> strategy, std::chrono::milliseconds think)
        : strategy_(std::move(strategy)), budget_{think, bots::DecisionBudget{}.max_candidates} {}

    Shot choose_shot(const rules::MatchState& state, int seat,
                     std::chrono::milliseconds waited) override {
        const std::lock_guard lock(mutex_);
        bots::DecisionBudget budget = budget_;
        budget.time = std::max(budget_.time - waited, kLeastThink);
        const auto before = strategy_->search_totals();
        const Shot shot = strategy_->choose_shot(state, seat, budget);
        const auto after = strategy_->search_totals();
        if (after.candidates > before.candidates) {
            const double seconds = after.seconds - before.seconds;
            spdlog::debug("bot {}: {} candidates in {:.1f} ms ({:.0f}/s)", strategy_->name(),
                          after.candidates - before.candidates, 1000.0 * seconds,
                          seconds > 0.0
                              ? static_cast<double>(after.candidates - before.candidates) / seconds
                              : 0.0);
        }
        return shot;
    }

private:
    std::mutex mutex_;
    std::unique_ptr<bots::Strategy> strategy_;
    bots::DecisionBudget budget_;
};

} // namespace

BotFactory make_strategy_bot_factory(std::uint64_t seed, std::chrono::milliseconds think) {
    auto next_seed = std::make_shared<std::atomic<std::uint64_t>>(seed);
    return [next_seed, think](proto::BotLevel level) -> std::shared_ptr<room::BotBrain> {
        const std::uint64_t bot_seed = next_seed->fetch_add(1);
        return std::make_shared<StrategyBrain>(bots::make_level_strategy(level, bot_seed), think);
    };
}

} // namespace carrom::server
