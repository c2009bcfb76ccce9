// carrom-client --frame-log in a real networked game: carrom-server (with a match store), a
// carrom-bot creating the room and carrom-client (--autoplay easy) joining it under Xvfb. Every
// line of the log parses; the client's own strokes are drawn moving from the first frame rendered
// after their release; the bot's strokes appear as frames of their turn with moving bodies; and
// carrom-sim --frame-error, with the server's journal of the game, finds every board the client
// drew at rest after a stroke equal to the server's final board.

#include "client_program.hpp"
#include "support/child_process.hpp"
#include "support/command_run.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using test_support::ServerProcess;
using test_support::TempDir;
using Clock = std::chrono::steady_clock;
using Json = nlohmann::json;
using namespace std::chrono_literals;

constexpr int kStrikerId = 19;

bool draws_striker(const Json& frame) {
    for (const Json& b : frame["bodies"]) {
        if (b[0] == kStrikerId) {
            return true;
        }
    }
    return false;
}

TEST(FrameLog, RecordsEveryFrameOfARealGameAndItsFinalBoards) {
    TempDir dir("carrom_frame_log");
    ServerProcess server({CARROM_SERVER_PATH,
                          dir.file("c.db"),
                          {"--shot-clock", "0", "--time-scale", "25", "--log-level", "warn"},
                          {},
                          0});
    ASSERT_TRUE(server.start()) << server.log();
    ChildProcess bot(
        {CARROM_BOT_PATH, "--url",     server.url(),      "--name", "Bot",      "--create",
         "--rule-set",    "freestyle", "--target-points", "20",     "--boards", "1",
         "--shot-clock",  "0",         "--strategy",      "random", "--seed",   "3",
         "--timeout",     "150"});
    const auto room = bot.wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s);
    ASSERT_TRUE(room) << bot.output();
    const std::string code = room->substr(5);
    const std::string frames_path = dir.file("frames.jsonl");
    const std::vector<std::string> argv = client_argv(
        {std::string("--url"), server.url(), std::string("--name"), std::string("Ana"),
         std::string("--join"), code, std::string("--mute"), std::string("--width"),
         std::string("600"), std::string("--height"), std::string("600"), std::string("--autoplay"),
         std::string("easy"), std::string("--frame-log"), frames_path, std::string("--final-state"),
         dir.file("final.json"), std::string("--timeout"), std::string("140")});
    ChildProcess client(argv, {client_asan_options()});
    const auto exit = client.wait_exit(Clock::now() + 150s);
    ASSERT_TRUE(exit) << client.output();
    ASSERT_EQ(*exit, 0) << client.output();

    std::ifstream in(frames_path);
    ASSERT_TRUE(in);
    std::vector<Json> frames;
    std::vector<Json> shots;
    std::string line;
    while (std::getline(in, line)) {
        const Json j = Json::parse(line, nullptr, false);
        ASSERT_TRUE(j.is_object()) << line;
        ASSERT_TRUE(j["ms"].is_number()) << line;
        if (j["kind"] == "shoot") {
            ASSERT_TRUE(j["turn"].is_number_integer()) << line;
            shots.push_back(j);
            continue;
        }
        ASSERT_EQ(j["kind"], "frame") << line;
        for (const char* key : {"frame", "render_s", "turn", "t", "delay_ms"}) {
            ASSERT_TRUE(j[key].is_number()) << key << " in " << line;
        }
        ASSERT_TRUE(j["predicted"].is_boolean() && j["playing"].is_boolean()) << line;
        ASSERT_TRUE(j["link"].is_string()) << line;
        for (const Json& b : j["bodies"]) {
            ASSERT_TRUE(b.is_array() && b.size() == 3) << line;
        }
        if (!frames.empty()) {
            EXPECT_EQ(j["frame"].get<long>(), frames.back()["frame"].get<long>() + 1);
            EXPECT_GE(j["ms"].get<double>(), frames.back()["ms"].get<double>());
        }
        frames.push_back(j);
    }
    ASSERT_FALSE(shots.empty()) << "the client never shot";
    std::set<int> own_turns;
    for (const Json& shot : shots) {
        own_turns.insert(shot["turn"].get<int>());
        EXPECT_TRUE(shot["predicted"].get<bool>()) << shot;
        // The release happens while a frame is made (after its board was rendered): the next
        // frame draws the stroke moving.
        std::size_t i = 0;
        while (i < frames.size() && frames[i]["ms"].get<double>() < shot["ms"].get<double>()) {
            ++i;
        }
        ASSERT_LT(i + 1, frames.size());
        const Json& next = frames[i + 1];
        EXPECT_EQ(next["turn"], shot["turn"]) << next;
        EXPECT_GT(next["t"].get<double>(), 0.0) << next;
        // Drawn as the client's prediction, or as the server's stroke when all of it arrived
        // before that frame (--time-scale 25 plays a stroke in a fraction of a second, and a frame
        // of the client under ASan can take longer): either way the stroke is being played.
        EXPECT_TRUE(next["predicted"].get<bool>() || next["playing"].get<bool>()) << next;
        EXPECT_TRUE(draws_striker(next)) << next;
    }
    // Frames of the bot's strokes in which the drawn striker moves.
    int moving = 0;
    for (std::size_t i = 1; i < frames.size(); ++i) {
        const Json& f = frames[i];
        if (own_turns.contains(f["turn"].get<int>()) || f["t"].get<double>() <= 0.0 ||
            !f["playing"].get<bool>() || frames[i - 1]["turn"] != f["turn"]) {
            continue;
        }
        for (const Json& b : f["bodies"]) {
            for (const Json& was : frames[i - 1]["bodies"]) {
                if (b[0] == kStrikerId && was[0] == kStrikerId && b != was) {
                    ++moving;
                }
            }
        }
    }
    EXPECT_GT(moving, 5);

    // The journal of the game from the match API, and the frames against its exact strokes.
    const ServerProcess::Http list = server.get("/matches?player=Bot&limit=1");
    ASSERT_EQ(list.status, 200) << list.body;
    const auto id = Json::parse(list.body)["matches"][0]["id"].get<std::string>();
    const ServerProcess::Http journal = server.get("/matches/" + id);
    ASSERT_EQ(journal.status, 200) << journal.body;
    std::ofstream(dir.file("journal.json")) << journal.body;
    const test_support::CommandRun sim =
        test_support::run_command(std::string(CARROM_SIM_PATH) + " --frame-error " + frames_path +
                                  " " + dir.file("journal.json"));
    ASSERT_EQ(sim.exit, 0) << sim.out;
    const Json measured = Json::parse(sim.out);
    EXPECT_GT(measured["samples"].get<long>(), 0) << sim.out;
    EXPECT_GT(measured["finals_checked"].get<int>(), 0) << sim.out;
    EXPECT_EQ(measured["finals_equal"], measured["finals_checked"]) << sim.out;
}

} // namespace
} // namespace carrom::client
