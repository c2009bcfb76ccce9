#include "stream_recorder.hpp"

#include "carrom/bots/bot_runner.hpp"
#include "carrom/bots/strategy.hpp"
#include "carrom/proto/codec.hpp"

#include <chrono>
#include <cmath>
#include <numbers>

namespace carrom::golden {

std::variant<std::vector<StreamLine>, std::string> record_stream(const RecordOptions& options) {
    bots::StrategyOptions strategy_options;
    strategy_options.name = options.strategy;
    if (options.strategy == "fouls") {
        // From the bottom baseline's left end (125, 520) at the bottom-left pocket (57, 543).
        strategy_options.name = "scripted";
        strategy_options.script = {Shot{300.0, -std::numbers::pi / 2.0, 8.0},
                                   Shot{125.0, std::atan2(23.0, -68.0), 5.0}};
    }
    strategy_options.seed = options.seed;
    auto made = bots::make_strategy(strategy_options);
    if (auto* error = std::get_if<std::string>(&made)) {
        return *error;
    }
    auto strategy = std::get<std::unique_ptr<bots::Strategy>>(std::move(made));

    bots::BotConfig config;
    config.url = options.url;
    config.name = "Asha";
    config.mode = bots::JoinMode::Create;
    config.create.seats = options.seats;
    config.create.options.boards = options.boards;
    proto::BotLevel level = proto::BotLevel::Medium;
    if (!proto::parse(options.level, level)) {
        return "no bot level " + options.level;
    }
    config.create.bot = proto::BotSeat{level, {}};
    config.games = 1;
    config.budget.time = std::chrono::milliseconds(50);
    config.auto_resume = false;

    std::vector<StreamLine> stream;
    const auto start = std::chrono::steady_clock::now();
    bots::BotRunner runner(config, *strategy);
    runner.on_message = [&](const proto::ServerMessage& message) {
        const std::chrono::duration<double> since = std::chrono::steady_clock::now() - start;
        stream.push_back({since.count(), proto::encode(message)});
    };
    runner.start();
    const auto timeout = std::chrono::duration_cast<std::chrono::milliseconds>(
        std::chrono::duration<double>(options.timeout_s));
    if (!runner.run_until_done(timeout)) {
        return "the match did not end within " + std::to_string(options.timeout_s) + " s";
    }
    if (!runner.summary().failure.empty()) {
        return runner.summary().failure;
    }
    return stream;
}

} // namespace carrom::golden
