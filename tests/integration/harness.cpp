#include "harness.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace carrom::integration {

std::unique_ptr<bots::Strategy> test_strategy(const std::string& name, std::uint64_t seed) {
    bots::StrategyOptions options;
    options.name = name;
    options.seed = seed;
    return std::get<std::unique_ptr<bots::Strategy>>(bots::make_strategy(options));
}

namespace {

using namespace std::chrono_literals;

std::unique_ptr<bots::Strategy> strategy_for(const MatchSpec& spec, std::uint64_t salt) {
    return test_strategy(spec.strategy, spec.seed * 1000 + salt);
}

// One match's bots; run() plays it on the calling thread.
struct MatchBots {
    MatchBots(const std::string& url, const MatchSpec& spec)
        : spec_(spec), first_(strategy_for(spec, 1)), second_(strategy_for(spec, 2)),
          watcher_(strategy_for(spec, 3)) {
        bots::BotConfig config;
        config.url = url;
        config.games = spec.games;
        config.budget.time = 200ms;
        config.name = "creator";
        config.mode = bots::JoinMode::Create;
        config.create = spec.create;
        creator = std::make_unique<bots::BotRunner>(config, *first_);
        base_ = config;
    }

    // Creates the room, then seats the others; steps everyone until done or timeout.
    void run() {
        const auto deadline = std::chrono::steady_clock::now() + spec_.timeout;
        creator->start();
        while (creator->summary().room_code.empty() && !creator->done() &&
               std::chrono::steady_clock::now() < deadline) {
            creator->step(20ms);
        }
        code = creator->summary().room_code;
        if (code.empty()) {
            return;
        }
        auto config = base_;
        config.mode = bots::JoinMode::Join;
        config.code = code;
        config.name = "joiner";
        if (spec_.spectator) {
            auto watch = config;
            watch.mode = bots::JoinMode::Spectate;
            watch.name = "watcher";
            spectator = std::make_unique<bots::BotRunner>(watch, *watcher_);
            spectator->start();
            // Seated before the game starts, so it sees every snapshot.
            while (spectator->room().has_value() == false && !spectator->done() &&
                   std::chrono::steady_clock::now() < deadline) {
                spectator->step(20ms);
            }
        }
        joiner = std::make_unique<bots::BotRunner>(config, *second_);
        joiner->start();
        for (;;) {
            const bool all_done =
                creator->done() && joiner->done() && (!spectator || spectator->done());
            if (all_done || std::chrono::steady_clock::now() >= deadline) {
                break;
            }
            creator->step(2ms);
            joiner->step(2ms);
            if (spectator) {
                spectator->step(2ms);
            }
        }
    }

    MatchRun result() const {
        MatchRun run;
        run.code = code;
        run.creator = creator->summary();
        if (joiner) {
            run.joiner = joiner->summary();
        }
        if (spectator) {
            run.spectator = spectator->summary();
        }
        if (!creator->done()) {
            run.creator.failure = "did not finish in time";
        }
        if (!joiner || !joiner->done()) {
            run.joiner.failure = "did not finish in time";
        }
        return run;
    }

    MatchSpec spec_;
    std::unique_ptr<bots::Strategy> first_;
    std::unique_ptr<bots::Strategy> second_;
    std::unique_ptr<bots::Strategy> watcher_;
    bots::BotConfig base_;
    std::unique_ptr<bots::BotRunner> creator;
    std::unique_ptr<bots::BotRunner> joiner;
    std::unique_ptr<bots::BotRunner> spectator;
    std::string code;
};

} // namespace

server::ServerSettings test_settings() {
    server::ServerSettings settings;
    settings.host = "127.0.0.1";
    settings.port = 0;
    settings.threads = 2;
    settings.shot_clock_s = 0.0;
    settings.grace_s = 30.0;
    settings.handshake_timeout_s = 10.0;
    settings.shutdown_grace_s = 1.0;
    settings.time_scale = kTestTimeScale;
    settings.max_connections_per_address = 100000; // every test client is on 127.0.0.1
    return settings;
}

TestServer::TestServer(server::ServerSettings settings)
    : server_(std::make_unique<server::Server>(std::move(settings))) {
    port_ = server_->listen();
    server_->start();
}

TestServer::~TestServer() {
    server_->shutdown();
}

MatchRun play_match(const std::string& url, const MatchSpec& spec) {
    MatchBots bots(url, spec);
    bots.run();
    return bots.result();
}

std::vector<MatchRun> play_matches(const std::string& url, const std::vector<MatchSpec>& specs) {
    std::vector<MatchRun> runs(specs.size());
    std::vector<std::thread> threads;
    threads.reserve(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) {
        threads.emplace_back([&, i] { runs[i] = play_match(url, specs[i]); });
    }
    for (auto& thread : threads) {
        thread.join();
    }
    return runs;
}

ManualClient::ManualClient(const std::string& url, const std::string& name)
    : connection_(net::Connection::open(url)), name_(name) {}

proto::Welcome ManualClient::hello(std::optional<std::string> token) {
    connection_->send(proto::Hello{proto::kProtocolVersion, name_, std::move(token)});
    const auto welcome = next<proto::Welcome>();
    EXPECT_TRUE(welcome.has_value()) << connection_->status().detail;
    return welcome.value_or(proto::Welcome{});
}

bool ManualClient::pull(std::chrono::steady_clock::time_point deadline) {
    while (std::chrono::steady_clock::now() < deadline) {
        connection_->wait(10ms);
        // The status first: a link seen closed has every message it received in the inbox.
        const bool closed = connection_->status().state == net::ConnectionState::Closed;
        auto messages = connection_->poll();
        if (!messages.empty()) {
            for (auto& m : messages) {
                history_.push_back(std::move(m));
            }
            return true;
        }
        if (closed) {
            return false;
        }
    }
    return false;
}

std::string ManualClient::next_error(std::chrono::milliseconds timeout) {
    const auto error = next<proto::Error>(timeout);
    return error ? error->code : std::string();
}

std::string ManualClient::wait_closed(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (connection_->status().state != net::ConnectionState::Closed &&
           std::chrono::steady_clock::now() < deadline) {
        connection_->wait(10ms);
        for (auto& m : connection_->poll()) {
            history_.push_back(std::move(m));
        }
    }
    for (auto& m : connection_->poll()) { // what came just before the close
        history_.push_back(std::move(m));
    }
    return connection_->status().detail;
}

void ManualClient::drain(std::chrono::milliseconds quiet) {
    const auto deadline = std::chrono::steady_clock::now() + quiet;
    while (std::chrono::steady_clock::now() < deadline) {
        connection_->wait(5ms);
        for (auto& m : connection_->poll()) {
            history_.push_back(std::move(m));
        }
    }
}

} // namespace carrom::integration
