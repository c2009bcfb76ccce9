// The carrom-bot executable end to end: two processes play a match on the in-process server and
// print their JSON summaries; failures give exit status 1 or 2 and plain words.
#include "harness.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <thread>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + "carrom_bot_cli_" + std::to_string(getpid()) + "_" + name;
}

// The room code a creating carrom-bot prints on stderr ("room CODE"), read from its stderr
// file within 5 s; "" if none came.
std::string wait_for_room_code(const std::string& err_path) {
    std::string code;
    for (int i = 0; i < 200 && code.empty(); ++i) {
        std::this_thread::sleep_for(25ms);
        std::ifstream err(err_path);
        std::string word;
        while (err >> word) {
            if (word == "room" && err >> code) {
                break;
            }
        }
    }
    return code;
}

TEST(BotCli, TwoBotProcessesPlayAMatch) {
    TestServer server;
    const std::string bot = CARROM_BOT_PATH;
    const std::string creator_err = temp_path("creator.err");
    const std::string timeout = "60";
    CommandRun creator;
    std::thread creator_thread([&] {
        creator = run_command(bot + " --url " + server.url() + " --create --rule-set freestyle" +
                              " --target-points 30 --shot-clock 0 --strategy sampling --seed 3" +
                              " --timeout " + timeout + " 2> " + creator_err);
    });
    const std::string code = wait_for_room_code(creator_err);
    ASSERT_EQ(code.size(), 6u);
    const CommandRun joiner = run_command(bot + " --url " + server.url() + " --join " + code +
                                          " --strategy random --seed 4 --timeout " + timeout);
    creator_thread.join();
    std::remove(creator_err.c_str());
    ASSERT_EQ(creator.exit, 0) << creator.out;
    ASSERT_EQ(joiner.exit, 0) << joiner.out;
    const auto a = nlohmann::json::parse(creator.out);
    const auto b = nlohmann::json::parse(joiner.out);
    EXPECT_EQ(a["ok"], true);
    EXPECT_EQ(b["ok"], true);
    EXPECT_EQ(a["room"], code);
    EXPECT_EQ(b["room"], code);
    EXPECT_EQ(a["seat"], 0);
    EXPECT_EQ(b["seat"], 1);
    EXPECT_EQ(a["games"], 1);
    EXPECT_EQ(a["scores"], b["scores"]);
    EXPECT_EQ(a["strategy"], "sampling");
    EXPECT_EQ(b["strategy"], "random");
    EXPECT_NE(a["result"], b["result"]);
    // A game to 30 points of freestyle's 320 ends when a side reaches them; the summary names
    // that end as the journal and the Match API do.
    EXPECT_EQ(a["reason"], "target_points");
    EXPECT_EQ(b["reason"], "target_points");
}

TEST(BotCli, TraceHasEveryShotSentAndTheSnapshotsThatFollowIt) {
    TestServer server;
    const std::string bot = CARROM_BOT_PATH;
    const std::string trace = temp_path("creator.trace");
    const std::string creator_err = temp_path("trace_creator.err");
    CommandRun creator;
    std::thread creator_thread([&] {
        creator =
            run_command(bot + " --url " + server.url() + " --create --rule-set freestyle" +
                        " --target-points 30 --shot-clock 0 --strategy sampling --seed 5" +
                        " --timeout 60 --log-level info --trace " + trace + " 2> " + creator_err);
    });
    const std::string code = wait_for_room_code(creator_err);
    ASSERT_EQ(code.size(), 6u);
    const CommandRun joiner = run_command(bot + " --url " + server.url() + " --join " + code +
                                          " --strategy random --seed 6 --timeout 60");
    creator_thread.join();
    std::remove(creator_err.c_str());
    ASSERT_EQ(creator.exit, 0) << creator.out;
    ASSERT_EQ(joiner.exit, 0) << joiner.out;
    // Logged at info on stderr; stdout holds the JSON summary alone.
    const auto summary = nlohmann::json::parse(creator.out);

    std::ifstream in(trace);
    std::vector<nlohmann::json> lines;
    for (std::string line; std::getline(in, line);) {
        lines.push_back(nlohmann::json::parse(line));
    }
    std::remove(trace.c_str());
    ASSERT_FALSE(lines.empty());
    int shoots = 0;
    int snapshots = 0;
    double previous_ms = 0.0;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto& line = lines[i];
        EXPECT_GE(line["ms"].get<double>(), previous_ms) << line.dump(); // one monotonic clock
        previous_ms = line["ms"].get<double>();
        const std::string kind = line["kind"];
        EXPECT_TRUE(kind == "shoot" || kind == "snapshot" || kind == "room_state" ||
                    kind == "notice")
            << line.dump();
        if (kind == "snapshot") {
            ++snapshots;
        }
        if (kind != "shoot") {
            continue;
        }
        ++shoots;
        EXPECT_TRUE(line.contains("x") && line.contains("angle") && line.contains("power"));
        // The shot's motion reaches its shooter: a delta of the same turn, later in the trace.
        const int turn = line["turn"];
        bool moved = false;
        for (std::size_t j = i + 1; j < lines.size() && !moved; ++j) {
            moved = lines[j]["kind"] == "snapshot" && lines[j]["turn"] == turn &&
                    lines[j]["keyframe"] == false && lines[j]["bodies"].get<int>() > 0;
        }
        EXPECT_TRUE(moved) << "no motion after the shot of turn " << turn;
    }
    EXPECT_EQ(shoots, summary["shots"].get<int>()); // sampling sends legal shots only
    EXPECT_EQ(snapshots, summary["snapshots"].get<int>());
}

TEST(BotCli, UnwritableTraceIsRefusedWithExitTwo) {
    const CommandRun ran =
        run_command(std::string(CARROM_BOT_PATH) +
                    " --url ws://127.0.0.1:1 --quick --trace /nonexistent/dir/t 2>&1");
    EXPECT_EQ(ran.exit, 2);
    EXPECT_NE(ran.out.find("--trace: cannot write /nonexistent/dir/t"), std::string::npos)
        << ran.out;
}

TEST(BotCli, ARoomCodeOutsideTheAlphabetIsRefusedWithExitTwo) {
    const CommandRun ran =
        run_command(std::string(CARROM_BOT_PATH) + " --url ws://127.0.0.1:1 --join abc123 2>&1");
    EXPECT_EQ(ran.exit, 2);
    EXPECT_EQ(ran.out, "carrom-bot: a room code is 6 characters from "
                       "ABCDEFGHJKMNPQRSTUVWXYZ23456789 (got \"abc123\")\n");
}

TEST(BotCli, UnreachableServerSaysSoAndExitsWithOne) {
    std::string url;
    {
        TestServer server;
        url = server.url();
    } // stopped: nothing listens on its port any more
    const CommandRun ran =
        run_command(std::string(CARROM_BOT_PATH) + " --url " + url + " --quick --timeout 10");
    EXPECT_EQ(ran.exit, 1);
    const auto summary = nlohmann::json::parse(ran.out);
    EXPECT_EQ(summary["ok"], false);
    EXPECT_EQ(summary["failure"], "Could not reach " + url.substr(5) + ": connection refused.");
}

TEST(BotCli, BadScriptIsRefusedWithTheLine) {
    const std::string script = temp_path("bad.jsonl");
    std::ofstream(script) << "{\"x\": 300, \"angle\": -1.5, \"power\": 20}\n{\"x\": 300}\n";
    const CommandRun ran = run_command(std::string(CARROM_BOT_PATH) +
                                       " --strategy scripted --script " + script + " 2>&1");
    std::remove(script.c_str());
    EXPECT_EQ(ran.exit, 2);
    EXPECT_NE(ran.out.find("line 2: missing field 'angle'."), std::string::npos) << ran.out;
}

} // namespace
} // namespace carrom::integration
