#include "carrom/bots/greedy_strategy.hpp"
#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/sampling_strategy.hpp"
#include "carrom/bots/scripted_strategy.hpp"

namespace carrom::bots {

namespace {
constexpr int kSamplingCandidates = 200; // per decision (about 2 ms on one core)
} // namespace

std::unique_ptr<Strategy> make_level_strategy(proto::BotLevel level, std::uint64_t seed) {
    GreedyOptions greedy;
    greedy.seed = seed;
    switch (level) {
    case proto::BotLevel::Random:
        return std::make_unique<RandomStrategy>(seed);
    case proto::BotLevel::Easy:
        greedy.level = SkillLevel::Easy;
        break;
    case proto::BotLevel::Medium:
        greedy.level = SkillLevel::Medium;
        break;
    case proto::BotLevel::Hard:
        greedy.level = SkillLevel::Hard;
        break;
    }
    return std::make_unique<GreedyStrategy>(greedy);
}

std::vector<std::string> strategy_names() {
    return {"random", "scripted", "sampling", "greedy"};
}

std::variant<std::unique_ptr<Strategy>, std::string> make_strategy(const StrategyOptions& options) {
    if (options.name == "random") {
        return std::unique_ptr<Strategy>(std::make_unique<RandomStrategy>(options.seed));
    }
    if (options.name == "sampling") {
        return std::unique_ptr<Strategy>(
            std::make_unique<SamplingStrategy>(options.seed, kSamplingCandidates));
    }
    if (options.name == "greedy") {
        const auto level = parse_skill_level(options.level);
        if (!level) {
            return "Unknown level '" + options.level +
                   "' for the greedy strategy (known: perfect, hard, medium, easy).";
        }
        GreedyOptions greedy;
        greedy.level = *level;
        greedy.seed = options.seed;
        return std::unique_ptr<Strategy>(std::make_unique<GreedyStrategy>(greedy));
    }
    if (options.name == "scripted") {
        if (options.script.empty()) {
            return std::string("The scripted strategy needs a script with at least one shot.");
        }
        return std::unique_ptr<Strategy>(std::make_unique<ScriptedStrategy>(options.script));
    }
    std::string known;
    for (const auto& name : strategy_names()) {
        known += (known.empty() ? "" : ", ") + name;
    }
    return "Unknown strategy '" + options.name + "' (known: " + known + ").";
}

} // namespace carrom::bots
