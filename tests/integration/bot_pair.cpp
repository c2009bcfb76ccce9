#include "bot_pair.hpp"

#include "journal_check.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace carrom::integration {

using namespace std::chrono_literals;

Pair::Pair(const std::string& url, std::uint64_t seed, bool rated)
    : first(test_strategy("sampling", seed * 10 + 1)),
      second(test_strategy("sampling", seed * 10 + 2)), url_(url) {
    const auto connect = [this](const bots::BotConfig& config) {
        return net::Connection::open(this->url(), config.connection);
    };
    bots::BotConfig config;
    config.url = url;
    config.budget.time = 60ms;
    config.name = "creator";
    config.mode = bots::JoinMode::Create;
    config.create.rule_set = proto::RuleSet::Icf; // one board: tens of strokes
    config.create.options.boards = 1;
    config.create.options.shot_clock_s = 4.0;
    config.create.rated = rated;
    if (rated) {
        config.identity = std::string(64, 'c');
    }
    creator = std::make_unique<bots::BotRunner>(config, *first);
    creator->connect = connect;
    creator->on_message = [this](const proto::ServerMessage& m) {
        if (std::holds_alternative<proto::ShotResult>(m)) {
            ++shots;
        }
        if (hook) {
            hook(m);
        }
    };
    creator->start();
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (creator->summary().room_code.empty() && !creator->done() &&
           std::chrono::steady_clock::now() < deadline) {
        creator->step(20ms);
    }
    config.name = "joiner";
    config.mode = bots::JoinMode::Join;
    config.code = creator->summary().room_code;
    if (rated) {
        config.identity = std::string(64, 'f'); // 'j' is not a hex digit
    }
    joiner = std::make_unique<bots::BotRunner>(config, *second);
    joiner->connect = connect;
    joiner->start();
}

void Pair::run(const std::function<bool()>& until, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!(creator->done() && joiner->done()) && !until() &&
           std::chrono::steady_clock::now() < deadline) {
        creator->step(2ms);
        if (until()) {
            break;
        }
        joiner->step(2ms);
    }
}

void Pair::drop() {
    creator->drop();
    joiner->drop();
}

void Pair::resume() {
    creator->resume();
    joiner->resume();
}

void Pair::move_to(const std::string& url) {
    const std::lock_guard lock(url_mutex_);
    url_ = url;
}

std::string Pair::url() const {
    const std::lock_guard lock(url_mutex_);
    return url_;
}

void Pair::expect_finished(int resumes) const {
    for (const auto* bot : {creator.get(), joiner.get()}) {
        EXPECT_TRUE(bot->summary().finished)
            << bot->summary().room_code << ": " << bot->summary().failure;
        EXPECT_EQ(bot->summary().resumes, resumes);
        EXPECT_EQ(bot->summary().errors.count("bad_token"), 0U);
    }
}

void PauseWatch::see(const proto::ServerMessage& m) {
    if (const auto* event = std::get_if<proto::Event>(&m)) {
        if (const auto* p = std::get_if<proto::PausedEvent>(event)) {
            ++paused;
            reason = p->reason;
            message = p->message;
            paused_at = std::chrono::steady_clock::now();
        } else if (std::holds_alternative<proto::ResumedEvent>(*event)) {
            ++resumed;
            resumed_at = std::chrono::steady_clock::now();
        }
    } else if (paused > resumed && (std::holds_alternative<proto::Snapshot>(m) ||
                                    std::holds_alternative<proto::ShotResult>(m))) {
        ++streamed_while_paused;
    }
}

void expect_new_matches_refused(const std::string& url) {
    ManualClient client(url, "latecomer");
    client.hello();
    proto::CreateRoom create;
    client.send(create);
    EXPECT_EQ(client.next_error(), "store_unavailable");
    create.bot = proto::BotSeat{};
    client.send(create);
    EXPECT_EQ(client.next_error(), "store_unavailable");
    client.send(proto::QuickMatch{});
    EXPECT_EQ(client.next_error(), "store_unavailable");
    const auto errors = client.history();
    const auto last = std::find_if(errors.rbegin(), errors.rend(), [](const auto& m) {
        return std::holds_alternative<proto::Error>(m);
    });
    ASSERT_NE(last, errors.rend());
    EXPECT_EQ(std::get<proto::Error>(*last).message,
              "The server cannot start a match now because its database does not answer; try "
              "again in a moment.");
}

test_support::ServerProcess::Options bot_server_options(const std::string& data) {
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = data;
    options.args = {"--time-scale",
                    "25",
                    "--grace",
                    "20",
                    "--log-level",
                    "info",
                    "--max-connections-per-address",
                    "1000"};
    return options;
}

int expect_finished_journals_clean(const test_support::ServerProcess& server, std::size_t count) {
    const auto json = nlohmann::json::parse(server.get("/matches?player=creator&limit=100").body);
    const auto& matches = json["matches"];
    EXPECT_EQ(matches.size(), count);
    int strokes = 0;
    for (const auto& m : matches) {
        const std::string id = m["id"];
        EXPECT_FALSE(m["result"].is_null()) << id;
        const JournalCheck check = check_journal(server.get("/matches/" + id).body);
        EXPECT_TRUE(check.problem.empty()) << id << ": " << check.problem;
        EXPECT_TRUE(check.game_over) << id;
        EXPECT_TRUE(check.turns_consecutive) << id;
        strokes += check.strokes;
    }
    return strokes;
}

} // namespace carrom::integration
