// A cluster behind its front (docs/cluster.md, docs/deploy.md): PostgreSQL of the test's own,
// three carrom-server instances (carrom-1..3, --lease 2, public URLs through the front's
// /i/<id>/ routes) and HAProxy with docker/haproxy.cfg; bots (BotRunner over real sockets) that
// follow redirects. Twenty matches created through random instances and through the front, some
// watched by spectators, and a quick match of two bots that reached different instances; one
// instance killed with SIGKILL while shots move: every match finishes, every journal replays
// clean with consecutive turns (one through carrom-sim --replay too) and each bot's final
// scores equal the stored result. Then SIGTERM drains of each instance in turn under load, each
// started again (a rolling restart): every match finishes.
#include "harness.hpp"
#include "journal_check.hpp"

#include "support/child_process.hpp"
#include "support/command_run.hpp"
#include "support/loopback_port.hpp"
#include "support/postgres_instance.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include "carrom/net/http_get.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

bool haproxy_installed() {
    return test_support::run_command("command -v haproxy >/dev/null 2>&1").exit == 0;
}

// One bot of the test, with its strategy.
struct FrontBot {
    std::string name;
    std::unique_ptr<bots::Strategy> strategy;
    std::unique_ptr<bots::BotRunner> runner;
};

class ClusterFront : public ::testing::Test {
protected:
    void SetUp() override {
        if (!haproxy_installed()) {
            GTEST_SKIP() << "haproxy is not installed (scripts/install-deps.sh installs it)";
        }
        front_port = test_support::unused_loopback_port();
        front = "ws://127.0.0.1:" + std::to_string(front_port) + "/";
        for (int n = 1; n <= 3; ++n) {
            const std::string id = "carrom-" + std::to_string(n);
            test_support::ServerProcess::Options options;
            options.program = CARROM_SERVER_PATH;
            options.data = url;
            options.port = test_support::unused_loopback_port();
            options.args = {"--instance-id",
                            id,
                            "--lease",
                            "2",
                            "--public-url",
                            front + "i/" + id + "/",
                            "--time-scale",
                            "25",
                            "--grace",
                            "30",
                            "--log-level",
                            "info",
                            "--max-connections-per-address",
                            "1000",
                            "--quick-match-bot",
                            "30"};
            instances.push_back(std::make_unique<test_support::ServerProcess>(options));
            ASSERT_NE(instances.back()->port(), 0) << instances.back()->log();
        }
        // docker/haproxy.cfg as it is, but for its per-address limit: every client here is
        // 127.0.0.1 (docs/deploy.md, "What the front costs", does the same).
        const char* source = std::getenv("CARROM_SOURCE_DIR"); // set by ctest (tests/CMakeLists)
        ASSERT_NE(source, nullptr);
        std::ifstream in(std::string(source) + "/docker/haproxy.cfg");
        std::stringstream text;
        text << in.rdbuf();
        std::string cfg = text.str();
        const auto limit = cfg.find("sc0_conn_cur gt 64");
        ASSERT_NE(limit, std::string::npos);
        cfg.replace(limit, 18, "sc0_conn_cur gt 10000");
        haproxy_config = dir.file("haproxy.cfg");
        std::ofstream(haproxy_config) << cfg;
        std::vector<std::string> env = {"CARROM_FRONT_BIND=127.0.0.1:" +
                                        std::to_string(front_port)};
        for (int n = 1; n <= 3; ++n) {
            env.push_back("CARROM_INSTANCE_" + std::to_string(n) + "=127.0.0.1:" +
                          std::to_string(instances[static_cast<std::size_t>(n - 1)]->port()));
        }
        haproxy = std::make_unique<test_support::ChildProcess>(
            std::vector<std::string>{"haproxy", "-db", "-f", haproxy_config}, env,
            dir.file("haproxy.log"));
        ASSERT_TRUE(haproxy->started());
        for (int n = 1; n <= 3; ++n) {
            ASSERT_TRUE(front_reaches(n)) << "carrom-" << n << " not reached through the front";
        }
    }

    // GET /i/carrom-N/healthz through the front answers 200 within 10 s.
    bool front_reaches(int n) const {
        const auto deadline = Clock::now() + 10s;
        while (Clock::now() < deadline) {
            const auto answer = net::http_get("http://127.0.0.1:" + std::to_string(front_port) +
                                                  "/i/carrom-" + std::to_string(n) + "/healthz",
                                              net::HttpLimits{});
            if (std::holds_alternative<net::HttpResponse>(answer)) {
                return true;
            }
            std::this_thread::sleep_for(100ms);
        }
        return false;
    }

    // A bot at url: create (a one-board ICF room with a 4 s shot clock), join or spectate code,
    // or quick match (with a player key: rated). Its connections go where its config says
    // (redirects move it).
    FrontBot& add_bot(const std::string& at, bots::JoinMode mode, const std::string& name,
                      const std::string& code = {},
                      std::optional<std::string> identity = std::nullopt) {
        FrontBot bot;
        bot.name = name;
        bot.strategy = test_strategy("sampling", 100 + bots_.size());
        bots::BotConfig config;
        config.url = at;
        config.budget.time = 30ms;
        config.name = name;
        config.mode = mode;
        config.code = code;
        config.create.rule_set = proto::RuleSet::Icf;
        config.create.options.boards = 1;
        config.create.options.shot_clock_s = 4.0;
        config.reconnect.give_up_after_s = 60.0;
        config.identity = std::move(identity);
        bot.runner = std::make_unique<bots::BotRunner>(config, *bot.strategy);
        bot.runner->on_message = [this](const proto::ServerMessage& m) {
            if (std::holds_alternative<proto::ShotResult>(m)) {
                ++shots;
            }
            if (hook) {
                hook(m);
            }
        };
        bot.runner->start();
        bots_.push_back(std::move(bot));
        return bots_.back();
    }

    // Steps every bot until all are done, `until` holds, or the timeout passes.
    void run(const std::function<bool()>& until, std::chrono::milliseconds timeout) {
        const auto deadline = Clock::now() + timeout;
        while (Clock::now() < deadline && !until()) {
            bool all_done = true;
            for (auto& bot : bots_) {
                if (!bot.runner->done()) {
                    all_done = false;
                    bot.runner->step(1ms);
                }
            }
            if (all_done) {
                return;
            }
        }
    }

    // Creator and joiner of `matches` rooms, each at a random address (the front, or an
    // instance's route), every fourth watched by a spectator through the front.
    void start_matches(int matches, std::uint64_t seed) {
        std::mt19937_64 random(seed);
        const auto somewhere = [&] {
            const auto pick = random() % 4;
            return pick == 0 ? front : front + "i/carrom-" + std::to_string(pick) + "/";
        };
        for (int i = 0; i < matches; ++i) {
            const std::string n = std::to_string(matches_started++);
            FrontBot& creator = add_bot(somewhere(), bots::JoinMode::Create, "creator" + n);
            const auto deadline = Clock::now() + 10s;
            while (creator.runner->summary().room_code.empty() && !creator.runner->done() &&
                   Clock::now() < deadline) {
                creator.runner->step(5ms);
            }
            const std::string code = creator.runner->summary().room_code;
            ASSERT_FALSE(code.empty()) << creator.runner->summary().failure;
            FrontBot& joiner = add_bot(somewhere(), bots::JoinMode::Join, "joiner" + n, code);
            // Seated (a redirect may come first): the match runs, nothing waits for a player.
            const bots::BotRunner& seated = *joiner.runner;
            run([&] { return seated.summary().seat >= 0 || seated.done(); }, 10s);
            ASSERT_GE(seated.summary().seat, 0) << seated.summary().failure;
            if (i % 4 == 0) { // (the first of each call)
                add_bot(front, bots::JoinMode::Spectate, "watcher" + n, code);
            }
        }
    }

    // Every bot finished; each player's final scores are its match's stored result; every
    // stored match of a creator replays clean with consecutive turns.
    // Every bot finished, but for what an instance that stops (SIGKILL or SIGTERM) does to a
    // match it ran: a spectator may end there (its place is not stored), and a player whose
    // match ended by a stroke stored but not yet streamed learns it ended (its stored result is
    // checked like the others).
    void expect_all_finished_and_stored() {
        const std::string http = "http://127.0.0.1:" + std::to_string(front_port);
        std::map<std::string, std::vector<int>> scores_by_room;
        for (const auto& bot : bots_) {
            const bots::BotSummary& s = bot.runner->summary();
            if (s.seat < 0 &&
                s.failure.find("no longer holds the spectator's place") != std::string::npos) {
                continue;
            }
            if (s.failure.find("ended while you were away") != std::string::npos) {
                scores_by_room.emplace(s.room_code, std::vector<int>{});
                continue;
            }
            EXPECT_TRUE(s.finished)
                << bot.name << " in " << s.room_code << ": " << s.failure << " (resumes "
                << s.resumes << ", redirects " << s.redirects << ")";
            // (a room moved before its match began keeps no seat: that resume is refused once
            // and its player joins the room again)
            EXPECT_LE(s.errors.count("bad_token"), moved_while_waiting.count(bot.name))
                << s.room_code;
            if (s.seat < 0) {
                continue;
            }
            auto [it, fresh] = scores_by_room.emplace(s.room_code, s.scores);
            if (!fresh && it->second.empty()) {
                it->second = s.scores;
            }
            EXPECT_TRUE(fresh || it->second == s.scores) << s.room_code;
        }
        int replayed = 0;
        for (const auto& [room, scores] : scores_by_room) {
            const auto listed = net::http_get(
                http + "/matches?player=" + room_creator(room) + "&limit=5", net::HttpLimits{});
            ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(listed)) << room;
            const auto json =
                nlohmann::json::parse(std::get<net::HttpResponse>(listed).body, nullptr, false);
            ASSERT_TRUE(json.is_object()) << room;
            bool found = false;
            for (const auto& m : json["matches"]) {
                if (m["room"] != room) {
                    continue;
                }
                found = true;
                EXPECT_FALSE(m["result"].is_null()) << room;
                if (!scores.empty()) { // (empty: no player of it saw its end)
                    EXPECT_EQ(m["scores"].get<std::vector<int>>(), scores) << room;
                }
                const auto journal = net::http_get(http + "/matches/" + m["id"].get<std::string>(),
                                                   net::HttpLimits{});
                ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(journal)) << room;
                const std::string& body = std::get<net::HttpResponse>(journal).body;
                const JournalCheck check = check_journal(body);
                EXPECT_TRUE(check.problem.empty()) << room << ": " << check.problem;
                EXPECT_TRUE(check.game_over) << room;
                EXPECT_TRUE(check.turns_consecutive) << room;
                if (replayed++ == 0) {
                    const std::string file = dir.file("journal.json");
                    std::ofstream(file, std::ios::binary) << body;
                    const auto replay = test_support::run_command(std::string(CARROM_SIM_PATH) +
                                                                  " --replay " + file);
                    EXPECT_EQ(replay.exit, 0) << replay.out;
                    const auto out = nlohmann::json::parse(replay.out, nullptr, false);
                    EXPECT_EQ(out.value("mismatches", -1), 0) << replay.out;
                    EXPECT_EQ(out.value("complete", false), true) << replay.out;
                }
            }
            EXPECT_TRUE(found) << room;
        }
    }

    // The name of the bot that created (or, quick match, took seat 0 of) the room.
    std::string room_creator(const std::string& room) const {
        for (const auto& bot : bots_) {
            if (bot.runner->summary().room_code == room && bot.runner->summary().seat == 0) {
                return bot.name;
            }
        }
        return {};
    }

    // The instance (1..3) that owns the most unfinished matches.
    int busiest_instance() const {
        const std::string out = postgres
                                    .sql(database, "SELECT owner_instance FROM matches WHERE "
                                                   "finished_ms IS NULL GROUP BY owner_instance "
                                                   "ORDER BY count(*) DESC LIMIT 1")
                                    .out;
        return out.rfind("carrom-", 0) == 0 ? std::stoi(out.substr(7)) : 1;
    }

    std::string log_of_all() const {
        std::string text =
            "matches (room, owner, epoch, unfinished, entries):\n" +
            postgres
                .sql(database, "SELECT room_code, owner_instance, owner_epoch, finished_ms IS "
                               "NULL, (SELECT count(*) FROM entries e WHERE e.match_id = m.id) "
                               "FROM matches m ORDER BY room_code")
                .out;
        for (const auto& instance : instances) {
            text += instance->log();
        }
        return text;
    }

    test_support::TempDir dir{"carrom_front"};
    test_support::PostgresInstance postgres;
    std::string database = postgres.create_database();
    std::string url = postgres.url(database);
    std::uint16_t front_port = 0;
    std::string front;
    std::string haproxy_config;
    std::vector<std::unique_ptr<test_support::ServerProcess>> instances;
    std::unique_ptr<test_support::ChildProcess> haproxy;
    std::vector<FrontBot> bots_;
    int matches_started = 0;                   // numbers the bots' names
    std::set<std::string> moved_while_waiting; // bots whose room was handed over before it began
    std::atomic<int> shots{0};
    std::function<void(const proto::ServerMessage&)> hook;
};

TEST_F(ClusterFront, TwentyMatchesAndAQuickMatchSurviveAnInstanceKilledWhileShotsMove) {
    ASSERT_NO_FATAL_FAILURE(start_matches(20, 35));
    // Two players who reached different instances are paired.
    add_bot(front + "i/carrom-1/", bots::JoinMode::Quick, "quick1");
    run([] { return false; }, 1s);
    add_bot(front + "i/carrom-3/", bots::JoinMode::Quick, "quick2");
    const bots::BotRunner& quick1 = *bots_[bots_.size() - 2].runner;
    const bots::BotRunner& quick2 = *bots_.back().runner;
    run([&] { return !quick1.summary().room_code.empty() && !quick2.summary().room_code.empty(); },
        10s);
    EXPECT_EQ(quick1.summary().room_code, quick2.summary().room_code);
    EXPECT_EQ(quick1.summary().redirects + quick2.summary().redirects, 1);
    // So are two identified players: a rated match, rated once whatever happens to its instance.
    add_bot(front + "i/carrom-2/", bots::JoinMode::Quick, "rated1", {}, std::string(64, 'a'));
    run([] { return false; }, 1s);
    add_bot(front + "i/carrom-1/", bots::JoinMode::Quick, "rated2", {}, std::string(64, 'b'));
    const bots::BotRunner& rated1 = *bots_[bots_.size() - 2].runner;
    const bots::BotRunner& rated2 = *bots_.back().runner;
    run([&] { return !rated1.summary().room_code.empty() && !rated2.summary().room_code.empty(); },
        10s);
    EXPECT_EQ(rated1.summary().room_code, rated2.summary().room_code);
    EXPECT_EQ(rated1.summary().redirects + rated2.summary().redirects, 1);
    run([&] { return shots >= 40; }, 60s);
    ASSERT_GE(shots, 40) << log_of_all();

    const int victim = busiest_instance();
    bool killed = false;
    hook = [&](const proto::ServerMessage& m) {
        if (!killed && std::holds_alternative<proto::Snapshot>(m)) {
            instances[static_cast<std::size_t>(victim - 1)]->kill9();
            killed = true;
        }
    };
    run([&] { return killed; }, 20s);
    ASSERT_TRUE(killed);
    hook = nullptr;
    run([] { return false; }, 150s);

    int redirects = 0;
    for (const auto& bot : bots_) {
        redirects += bot.runner->summary().redirects;
    }
    EXPECT_GT(redirects, 0);
    // A spectator's place is not kept when its match's instance dies (only seats are stored):
    // the spectators of the killed instance's matches may end there.
    expect_all_finished_and_stored();
    EXPECT_EQ(postgres.sql(database, "SELECT count(*) FROM rating_changes").out, "2\n");
    if (HasFailure()) {
        std::fprintf(stderr, "instances:\n%s", log_of_all().c_str());
    }
}

TEST_F(ClusterFront, EveryMatchFinishesThroughADrainAndARollingRestartOfAllThree) {
    for (int n = 1; n <= 3; ++n) {
        // Each instance drains under load: new matches, some strokes played.
        ASSERT_NO_FATAL_FAILURE(start_matches(6, 36 + static_cast<std::uint64_t>(n)));
        const int before = shots;
        run([&] { return shots >= before + 10; }, 30s);
        // And a room on it that waits for its second player.
        const std::string name = "waiter" + std::to_string(n);
        FrontBot& waiter =
            add_bot(front + "i/carrom-" + std::to_string(n) + "/", bots::JoinMode::Create, name);
        run([&] { return !waiter.runner->summary().room_code.empty(); }, 10s);
        const std::string code = waiter.runner->summary().room_code;
        ASSERT_FALSE(code.empty()) << waiter.runner->summary().failure;
        moved_while_waiting.insert(name);
        auto& instance = *instances[static_cast<std::size_t>(n - 1)];
        instance.terminate(); // drains: its matches and rooms go to the others, players follow
        EXPECT_TRUE(instance.start()) << instance.log();
        ASSERT_TRUE(front_reaches(n));
        // As a rolling restart waits for each instance's readiness: the moved players settle
        // (a player still on its way to an instance that drains would have to find it again).
        run([] { return false; }, 2s);
        // The waiting room's friend comes with the code, through the front.
        add_bot(front, bots::JoinMode::Join, "friend" + std::to_string(n), code);
    }
    run([] { return false; }, 150s);
    EXPECT_EQ(
        postgres.sql(database, "SELECT count(*) FROM matches WHERE finished_ms IS NOT NULL").out,
        "21\n");
    EXPECT_NE(log_of_all().find("matches handed over"), std::string::npos);
    expect_all_finished_and_stored();
    if (HasFailure()) {
        std::fprintf(stderr, "instances:\n%s", log_of_all().c_str());
    }
}

} // namespace
} // namespace carrom::integration
