// Recovery after a restart (docs/server.md): carrom-server --data as a real process, bots playing
// over real sockets (the in-process BotRunner: the test drops and resumes them around the
// restart with their resume tokens, or they resume by themselves with back-off). kill -9 while a
// player aims, kill -9 while a shot moves, SIGTERM with 20 matches running: the server restarts on
// the same port and data, recovers the matches, the bots resume and finish, every journal replays
// clean with consecutive turns. The kill -9 case runs on a PostgreSQL store too (a server of the
// test's own, tests/support/postgres_instance.hpp).
#include "bot_pair.hpp"
#include "harness.hpp"

#include "support/postgres_instance.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include "carrom/physics_version.hpp"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <filesystem>
#include <future>
#include <thread>

#include <stdlib.h>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

class RecoveryDir : public test_support::TempDir {
public:
    RecoveryDir() : test_support::TempDir("carrom_recovery") {}
};

// carrom-server --data on a port (0: any), logging at info.
std::unique_ptr<test_support::ServerProcess> start_server(const std::string& data) {
    test_support::ServerProcess::Options options = bot_server_options(data);
    if (data.rfind("postgresql://", 0) == 0) { // cluster mode, one instance of a fixed id
        options.args.insert(options.args.end(),
                            {"--instance-id", "recovery", "--public-url", "ws://127.0.0.1:7777"});
    }
    return std::make_unique<test_support::ServerProcess>(options);
}

// The number in the "recovered N matches" line of this start's log (-1 if none came).
int recovered(const test_support::ServerProcess& server) {
    const auto line = server.wait_log("] recovered ", std::chrono::steady_clock::now() + 10s);
    if (!line) {
        return -1;
    }
    return std::stoi(line->substr(line->find("recovered ") + 10));
}

// Plays a match to its fourth stroke, kills the server (SIGKILL) when `moment` says so, restarts
// it on the same port and data; the bots resume and finish.
// by_themselves: the bots are not dropped and resumed by the test; they notice the lost connection
// and resume with back-off (BotRunner's auto_resume, as carrom-bot does). data: the store
// (--data), an SQLite file in a temporary directory unless given.
void kill_and_recover(const std::function<bool(const proto::ServerMessage&)>& moment,
                      bool by_themselves = false, std::string data = {}) {
    RecoveryDir dir;
    auto server = start_server(data.empty() ? dir.file("c.db") : data);
    const std::uint16_t port = server->port();
    ASSERT_NE(port, 0);
    Pair pair(server->url(), 7);
    ASSERT_FALSE(pair.creator->summary().room_code.empty());
    bool killed = false;
    pair.hook = [&](const proto::ServerMessage& m) {
        if (!killed && pair.shots >= 3 && moment(m)) {
            server->kill9();
            killed = true;
            if (!by_themselves) {
                pair.drop(); // before the creator's step sees its connection lost
            }
        }
    };
    pair.run([&] { return killed; }, 20s);
    ASSERT_TRUE(killed) << pair.shots << " shots; " << pair.creator->summary().failure << "; "
                        << pair.joiner->summary().failure;
    pair.hook = nullptr;

    ASSERT_TRUE(server->restart()) << server->log();
    ASSERT_EQ(server->port(), port);
    EXPECT_EQ(recovered(*server), 1);
    if (!by_themselves) {
        pair.resume();
    }
    pair.run([] { return false; }, 25s);
    pair.expect_finished();
    if (::testing::Test::HasFailure()) {
        std::fprintf(stderr, "server:\n%s", server->log().c_str());
    }
    EXPECT_GT(expect_finished_journals_clean(*server, 1), 3);
}

TEST(RecoveryProcess, KilledWhileAPlayerAimsTheBotsResumeAndFinish) {
    kill_and_recover([](const proto::ServerMessage& m) {
        const auto* event = std::get_if<proto::Event>(&m);
        return event != nullptr && std::holds_alternative<proto::TurnEvent>(*event);
    });
}

TEST(RecoveryProcess, KilledWhileAShotMovesTheBotsResumeAndFinish) {
    kill_and_recover(
        [](const proto::ServerMessage& m) { return std::holds_alternative<proto::Snapshot>(m); });
}

TEST(RecoveryProcess, KilledWhileAShotMovesTheBotsResumeByThemselvesAndFinish) {
    kill_and_recover(
        [](const proto::ServerMessage& m) { return std::holds_alternative<proto::Snapshot>(m); },
        true);
}

// The same on PostgreSQL (cluster mode, one instance): the restarted server, of the same instance
// id, claims the killed one's matches at its start and recovers them.
TEST(RecoveryProcess, OnPostgresqlKilledWhileAShotMovesTheBotsResumeAndFinish) {
    test_support::PostgresInstance postgres;
    kill_and_recover(
        [](const proto::ServerMessage& m) { return std::holds_alternative<proto::Snapshot>(m); },
        false, postgres.url(postgres.create_database()));
}

TEST(RecoveryProcess, AJournalOfAnotherPhysicsVersionIsNotResumedAndStaysInTheStore) {
    RecoveryDir dir;
    auto server = start_server(dir.file("c.db"));
    const std::uint16_t port = server->port();
    ASSERT_NE(port, 0);
    Pair pair(server->url(), 9);
    pair.run([&] { return pair.shots >= 2; }, 20s);
    ASSERT_GE(pair.shots, 2);
    server->terminate(10s);
    pair.drop();
    std::string id;
    {
        // The match as another physics version would have written it.
        SQLite::Database db(dir.file("c.db"), SQLite::OPEN_READWRITE);
        SQLite::Statement read(db, "SELECT id, head FROM matches");
        ASSERT_TRUE(read.executeStep());
        id = read.getColumn(0).getString();
        auto head = nlohmann::json::parse(read.getColumn(1).getString());
        auto& versions = head.contains("versions") ? head["versions"] : head["match"]["versions"];
        versions["physics"] = versions["physics"].get<int>() + 1;
        SQLite::Statement write(db, "UPDATE matches SET head = ?, physics_version = "
                                    "physics_version + 1 WHERE id = ?");
        write.bind(1, head.dump());
        write.bind(2, id);
        ASSERT_EQ(write.exec(), 1);
    }
    ASSERT_TRUE(server->restart()) << server->log();
    ASSERT_EQ(server->port(), port);
    EXPECT_EQ(recovered(*server), 0);
    const auto logged = server->wait_log("match " + id + " not recovered (left in the store)",
                                         std::chrono::steady_clock::now() + 1s);
    ASSERT_TRUE(logged) << server->log();
    EXPECT_NE(logged->find("physics"), std::string::npos) << *logged;
    const auto journal = nlohmann::json::parse(server->get("/matches/" + id).body);
    EXPECT_EQ(journal["match"]["versions"]["physics"].get<int>(), kPhysicsVersion + 1);
    const auto list = nlohmann::json::parse(server->get("/matches?player=creator&limit=5").body);
    ASSERT_EQ(list["matches"].size(), 1U);
    EXPECT_TRUE(list["matches"][0]["finished_ms"].is_null());
    // Its players' tokens are unknown: no seat to give back.
    pair.creator->resume();
    pair.creator->run_until_done(5s);
    EXPECT_EQ(pair.creator->summary().errors.count("bad_token"), 1U);
    EXPECT_NE(pair.creator->summary().failure.find("bad_token"), std::string::npos)
        << pair.creator->summary().failure;
}

TEST(RecoveryProcess, SigtermWithTwentyMatchesRunningAllTwentyFinishAfterTheRestart) {
    RecoveryDir dir;
    auto server = start_server(dir.file("c.db"));
    const std::uint16_t port = server->port();
    ASSERT_NE(port, 0);
    constexpr int kMatches = 20;
    std::vector<std::unique_ptr<Pair>> pairs;
    for (int i = 0; i < kMatches; ++i) {
        pairs.push_back(std::make_unique<Pair>(server->url(), static_cast<std::uint64_t>(100 + i)));
        ASSERT_FALSE(pairs.back()->creator->summary().room_code.empty());
    }
    auto run_all = [&](bool to_the_end, std::chrono::milliseconds timeout) {
        std::vector<std::future<void>> runs;
        for (auto& pair : pairs) {
            Pair* p = pair.get();
            runs.push_back(std::async(std::launch::async, [p, to_the_end, timeout] {
                p->run([p, to_the_end] { return !to_the_end && p->shots >= 2; }, timeout);
            }));
        }
        for (auto& run : runs) {
            run.get();
        }
    };
    run_all(false, 15s);
    for (const auto& pair : pairs) {
        ASSERT_GE(pair->shots, 2) << pair->creator->summary().failure;
        ASSERT_FALSE(pair->creator->done()) << "a match ended before the restart";
    }
    server->terminate(10s); // SIGTERM: connections closed, the store flushed
    for (auto& pair : pairs) {
        pair->drop();
    }

    ASSERT_TRUE(server->restart()) << server->log();
    ASSERT_EQ(server->port(), port);
    EXPECT_EQ(recovered(*server), kMatches);
    for (auto& pair : pairs) {
        pair->resume();
    }
    run_all(true, 28s);
    for (const auto& pair : pairs) {
        pair->expect_finished();
    }
    const int strokes = expect_finished_journals_clean(*server, kMatches);
    EXPECT_GT(strokes, 3 * kMatches);
    std::fprintf(stderr, "%d strokes; first match's end: %s\n", strokes,
                 pairs[0]->creator->summary().last_reason.c_str());
}

} // namespace
} // namespace carrom::integration
