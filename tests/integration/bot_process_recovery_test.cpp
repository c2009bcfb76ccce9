// Recovery after a crash with carrom-bot processes (docs/server.md, docs/bots.md): carrom-server
// --data as a program, two carrom-bot programs playing through it; the server is killed (SIGKILL)
// while a player aims or while a shot moves, the moment read from its /metrics, and restarted on
// the same port and data. The bots resume by themselves and finish; the match's journal (GET
// /matches/ID) replays clean through carrom-sim --replay, with consecutive turn numbers.
#include "journal_check.hpp"

#include "support/child_process.hpp"
#include "support/command_run.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;
using test_support::ChildProcess;
using test_support::ServerProcess;
using Clock = std::chrono::steady_clock;

// A carrom-bot playing one game; `play`: its strategy options, `how`: how it gets into the room.
ChildProcess start_bot(const ServerProcess& server, const std::string& name,
                       const std::string& seed, const std::vector<std::string>& play,
                       const std::vector<std::string>& how) {
    std::vector<std::string> argv{
        CARROM_BOT_PATH, "--url", server.url(),   "--name", name,        "--seed", seed,
        "--games",       "1",     "--resume-for", "20",     "--timeout", "60"};
    argv.insert(argv.end(), play.begin(), play.end());
    argv.insert(argv.end(), how.begin(), how.end());
    return ChildProcess(argv);
}

// The server's shot and snapshot counters (/metrics); -1 when it did not answer.
struct Counters {
    long shots = -1;
    long snapshots = -1;
    long games = -1; // games in progress
};

Counters counters(const ServerProcess& server) {
    Counters c;
    std::istringstream lines(server.get("/metrics").body);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.rfind("carrom_shots_total ", 0) == 0) {
            c.shots = std::stol(line.substr(19));
        } else if (line.rfind("carrom_snapshots_total ", 0) == 0) {
            c.snapshots = std::stol(line.substr(23));
        } else if (line.rfind("carrom_matches ", 0) == 0) {
            c.games = std::stol(line.substr(15));
        }
    }
    return c;
}

enum class Moment { Aiming, Moving };

// Polls /metrics until the match is in `moment`: Moving, after at least three strokes, the poll
// where the latest stroke's first snapshots went out (its stream has just begun); Aiming, after
// at least one stroke, the game still on, the latest stroke streamed and then no shot and no
// snapshot for 8 ms (at --snapshot-hz 240 snapshots go out every 4 ms while a shot moves: the
// player to move is thinking; a greedy bot decides in about 10-20 ms). False when the deadline
// passes first or the game ends before the moment is seen (greedy bots on an idle machine can
// finish a board in under 2 s).
bool wait_for(const ServerProcess& server, Moment moment, Clock::time_point deadline) {
    Counters last = counters(server);
    bool streamed = false; // snapshots went out since the latest stroke was accepted
    auto quiet_since = Clock::now();
    while (Clock::now() < deadline) {
        const Counters now = counters(server);
        const auto at = Clock::now();
        if (now.shots >= 1 && now.games == 0) {
            return false; // the game is over: the moment was missed
        }
        if (now.shots != last.shots) {
            streamed = false;
            quiet_since = at;
        } else if (now.snapshots != last.snapshots) {
            const bool began = !streamed;
            streamed = true;
            quiet_since = at;
            if (moment == Moment::Moving && began && now.shots >= 3) {
                return true;
            }
        } else if (moment == Moment::Aiming && streamed && now.shots >= 1 && now.games == 1 &&
                   at - quiet_since >= 8ms) {
            return true;
        }
        last = now;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

// The bot's exit code and its JSON summary (stdout's last line).
nlohmann::json finish(ChildProcess& bot, Clock::time_point deadline) {
    const auto exit = bot.wait_exit(deadline);
    EXPECT_EQ(exit.value_or(-1), 0) << bot.output();
    const auto& out = bot.lines(ChildProcess::Stream::Out);
    return out.empty() ? nlohmann::json() : nlohmann::json::parse(out.back(), nullptr, false);
}

// One ICF board between two carrom-bots playing `play`, the server killed at `moment`. Sets
// `missed` (and checks nothing) when the game ended before the moment came.
void kill_and_recover(Moment moment, const std::vector<std::string>& play, bool& missed) {
    missed = false;
    test_support::TempDir dir("carrom_bot_recovery");
    ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = dir.file("carrom.db");
    options.args = {"--time-scale", "25", "--snapshot-hz", "240",
                    "--grace",      "20", "--log-level",   "info"};
    ServerProcess server(options);
    const std::uint16_t port = server.port();
    ASSERT_NE(port, 0) << server.log();

    ChildProcess ann =
        start_bot(server, "Ann", "3", play,
                  {"--create", "--rule-set", "icf", "--boards", "1", "--shot-clock", "0"});
    const auto room = ann.wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s);
    ASSERT_TRUE(room) << ann.output();
    ChildProcess ben = start_bot(server, "Ben", "4", play, {"--join", room->substr(5)});

    if (!wait_for(server, moment, Clock::now() + 20s)) {
        missed = counters(server).games == 0;
        ASSERT_TRUE(missed) << ann.output() << ben.output() << server.log();
        return;
    }
    server.kill9();
    ASSERT_TRUE(server.restart()) << server.log();
    ASSERT_EQ(server.port(), port);
    EXPECT_TRUE(server.wait_log("recovered 1 matches", Clock::now() + 5s)) << server.log();

    const auto deadline = Clock::now() + 40s;
    const auto a = finish(ann, deadline);
    const auto b = finish(ben, deadline);
    ASSERT_TRUE(a.is_object() && b.is_object()) << ann.output() << ben.output();
    for (const auto* s : {&a, &b}) {
        EXPECT_EQ((*s)["ok"], true) << s->dump();
        EXPECT_GE((*s)["resumes"].get<int>(), 1) << s->dump();
        EXPECT_EQ((*s)["games"], 1) << s->dump();
    }
    EXPECT_EQ(a["scores"], b["scores"]);
    EXPECT_NE(a["result"], b["result"]);

    const auto list = nlohmann::json::parse(server.get("/matches?player=Ann&limit=5").body);
    ASSERT_EQ(list["matches"].size(), 1U) << list.dump();
    const std::string id = list["matches"][0]["id"];
    EXPECT_FALSE(list["matches"][0]["result"].is_null()) << list.dump();
    const std::string journal = server.get("/matches/" + id).body;
    const JournalCheck check = check_journal(journal);
    EXPECT_TRUE(check.problem.empty()) << check.problem;
    EXPECT_TRUE(check.game_over);
    EXPECT_TRUE(check.turns_consecutive);
    EXPECT_GT(check.strokes, 3);
    EXPECT_EQ(check.first_turn, 0);                                   // the first stroke is turn 0
    EXPECT_EQ(check.last_turn - check.first_turn + 1, check.strokes); // no clock expiries
    const std::string file = dir.file("journal.json");
    std::ofstream(file, std::ios::binary) << journal;
    const test_support::CommandRun replay =
        test_support::run_command(std::string(CARROM_SIM_PATH) + " --replay " + file);
    EXPECT_EQ(replay.exit, 0) << replay.out;
    const auto replayed = nlohmann::json::parse(replay.out, nullptr, false);
    EXPECT_EQ(replayed.value("mismatches", -1), 0) << replay.out;
    EXPECT_EQ(replayed.value("complete", false), true) << replay.out;
    if (::testing::Test::HasFailure()) {
        std::fprintf(stderr, "server:\n%s", server.log().c_str());
    }
}

// kill_and_recover in a new game while the moment is missed, at most three games.
void kill_and_recover_within(Moment moment, const std::vector<std::string>& play) {
    bool missed = true;
    for (int game = 0; game < 3 && missed && !::testing::Test::HasFailure(); ++game) {
        kill_and_recover(moment, play, missed);
    }
    EXPECT_FALSE(missed) << "three games ended before the moment to kill the server came";
}

TEST(RecoveryProcess, CarromBotProcessesResumeAndFinishAfterAKillWhileAPlayerAims) {
    // Greedy bots search for up to --think-ms on each decision: the aiming to kill the server in.
    kill_and_recover_within(Moment::Aiming,
                            {"--strategy", "greedy", "--level", "medium", "--think-ms", "250"});
}

TEST(RecoveryProcess, CarromBotProcessesResumeAndFinishAfterAKillWhileAShotMoves) {
    // Sampling bots decide at once: a quick game.
    kill_and_recover_within(Moment::Moving, {"--strategy", "sampling", "--think-ms", "60"});
}

} // namespace
} // namespace carrom::integration
