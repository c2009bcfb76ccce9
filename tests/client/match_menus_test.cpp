// The desktop client's menus against a real carrom-server and its bot, driven by --input (keys
// and clicks as a player gives them) and read back from the screenshot report's "ui": Leave asks
// first and Stay (button or Escape) keeps the match; Leave and mute are in the bottom bar and on
// keys; the settings file keeps the mute and the volume across a restart; the rules screen opens
// from the match at the room's rule set and from the lobby; the first-game tips step and skip;
// the message log lies beside or under the board, never over it, without a line twice; the
// lobby's rule set, bot level and name reach the room.

#include "client_program.hpp"
#include "support/child_process.hpp"
#include "support/read_file.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using test_support::ServerProcess;
using test_support::TempDir;
using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

class MatchMenusTest : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(server_.start()) << server_.log(); }

    // Runs carrom-client with `room` (flags asking for a room; empty: the lobby) and `input`,
    // at width x 900; returns its screenshot report.
    Json run(const std::vector<std::string>& room, const std::string& input, int width = 900) {
        const std::string report = dir_.file("report.json");
        std::vector<std::string> args{"--url",
                                      server_.url(),
                                      "--mute",
                                      "--settings",
                                      settings(),
                                      "--width",
                                      std::to_string(width),
                                      "--height",
                                      "900",
                                      "--frames",
                                      "20",
                                      "--screenshot",
                                      dir_.file("shot.png"),
                                      "--report",
                                      report,
                                      "--timeout",
                                      "40"};
        args.insert(args.end(), room.begin(), room.end());
        if (!input.empty()) {
            args.push_back("--input");
            args.push_back(input);
        }
        ChildProcess client(client_argv(args), {client_asan_options()});
        const auto exit = client.wait_exit(Clock::now() + 50s);
        EXPECT_TRUE(exit && *exit == 0) << client.output();
        const Json j = Json::parse(test_support::read_file(report), nullptr, false);
        EXPECT_TRUE(j.is_object()) << client.output();
        return j.is_object() ? j : Json::object();
    }

    std::string settings() const { return dir_.file("settings.json"); }

    static std::vector<std::string> vs_bot(const std::string& rules = "icf") {
        return {"--name", "Tester", "--vs-bot", "easy", "--rule-set", rules};
    }

    TempDir dir_{"carrom_match_menus"};
    ServerProcess server_{{CARROM_SERVER_PATH,
                           "none",
                           {"--shot-clock", "0", "--bot-think-ms", "20000", "--log-level", "warn"},
                           {},
                           0}};
};

TEST_F(MatchMenusTest, LeaveAsksFirstAndStayKeepsTheMatch) {
    Json r = run(vs_bot(), "bar:3");
    EXPECT_EQ(r["ui"]["open"], "leave");
    EXPECT_EQ(r["ui"]["leave_text"], "You lose this game: Bot (easy) wins it by forfeit.");
    EXPECT_EQ(r["phase"], "aiming");

    r = run(vs_bot(), "bar:3,dialog:0");
    EXPECT_EQ(r["ui"]["open"], "");
    EXPECT_EQ(r["phase"], "aiming") << "Stay keeps the match";
    EXPECT_FALSE(r["ui"]["lobby"].get<bool>());

    r = run(vs_bot(), "l,Escape");
    EXPECT_EQ(r["ui"]["open"], "");
    EXPECT_EQ(r["phase"], "aiming") << "Escape answers Stay";

    r = run(vs_bot(), "l,Enter");
    EXPECT_TRUE(r["ui"]["lobby"].get<bool>()) << "Enter leaves";
}

TEST_F(MatchMenusTest, MuteAndVolumeAreKeptAcrossARestart) {
    Json r = run(vs_bot(), "m,bar:1,dialog:1");
    EXPECT_TRUE(r["ui"]["settings"]["muted"].get<bool>());
    EXPECT_EQ(r["ui"]["settings"]["volume"], 90);
    EXPECT_EQ(r["ui"]["open"], "settings");
    const Json file = Json::parse(test_support::read_file(settings()), nullptr, false);
    EXPECT_EQ(file["muted"], true);
    EXPECT_EQ(file["volume"], 90);

    r = run(vs_bot(), "");
    EXPECT_TRUE(r["ui"]["settings"]["muted"].get<bool>()) << "muted after a restart";
    EXPECT_EQ(r["ui"]["settings"]["volume"], 90);

    r = run(vs_bot(), "bar:2");
    EXPECT_FALSE(r["ui"]["settings"]["muted"].get<bool>()) << "the Sound button unmutes";
}

TEST_F(MatchMenusTest, RulesOpenFromTheMatchAndTheLobby) {
    Json r = run(vs_bot("freestyle"), "h");
    EXPECT_EQ(r["ui"]["open"], "rules");
    EXPECT_EQ(r["ui"]["rules_tab"], 2) << "at the room's rule set (freestyle)";
    r = run(vs_bot("discpool"), "bar:0");
    EXPECT_EQ(r["ui"]["open"], "rules");
    EXPECT_EQ(r["ui"]["rules_tab"], 3);
    r = run(vs_bot(), "bar:0,dialog:5");
    EXPECT_EQ(r["ui"]["open"], "") << "Close";

    r = run({"--name", "Tester"}, "F1");
    EXPECT_TRUE(r["ui"]["lobby"].get<bool>());
    EXPECT_EQ(r["ui"]["open"], "rules");
    r = run({"--name", "Tester"}, "lobby:11");
    EXPECT_EQ(r["ui"]["open"], "rules") << "the lobby's How to play button";
}

TEST_F(MatchMenusTest, TipsStepAndSkipForGood) {
    Json r = run(vs_bot(), "tips:0");
    EXPECT_EQ(r["ui"]["tip"], 1);
    r = run(vs_bot(), "tips:1");
    EXPECT_EQ(r["ui"]["tip"], -1);
    EXPECT_TRUE(r["ui"]["settings"]["coached"].get<bool>());
    r = run(vs_bot(), "");
    EXPECT_EQ(r["ui"]["tip"], -1) << "skipped tips stay skipped";
}

// The log and its lines never overlap the board; no line is shown twice.
void expect_log_off_the_board(const Json& r) {
    const double bx = r["board"]["x"].get<double>();
    const double by = r["board"]["y"].get<double>();
    const double side = r["board"]["side"].get<double>();
    const auto off = [&](const Json& q) {
        const double x = q["x"].get<double>();
        const double y = q["y"].get<double>();
        return x >= bx + side || x + q["w"].get<double>() <= bx || y >= by + side ||
               y + q["h"].get<double>() <= by;
    };
    EXPECT_TRUE(off(r["ui"]["side"])) << r["ui"]["side"];
    std::set<std::string> texts;
    ASSERT_FALSE(r["ui"]["messages"].empty()) << "no line to check";
    for (const Json& m : r["ui"]["messages"]) {
        EXPECT_TRUE(off(m)) << m;
        EXPECT_TRUE(texts.insert(m["text"].get<std::string>()).second) << "twice: " << m;
    }
}

TEST_F(MatchMenusTest, MessagesLieBesideOrUnderTheBoard) {
    // Tips skipped first, so the whole side area holds lines.
    Json r = run(vs_bot(), "tips:1,h,Escape");
    expect_log_off_the_board(r);
    EXPECT_GE(r["ui"]["side"]["y"].get<double>(),
              r["board"]["y"].get<double>() + r["board"]["side"].get<double>())
        << "under the board of a square window";
    r = run(vs_bot(), "h,Escape", 1280);
    expect_log_off_the_board(r);
    EXPECT_GE(r["ui"]["side"]["x"].get<double>(),
              r["board"]["x"].get<double>() + r["board"]["side"].get<double>())
        << "beside the board of a wide window";
}

TEST_F(MatchMenusTest, LobbyChoosesRuleSetBotLevelAndName) {
    // Rule set twice (ICF, classic, freestyle), bot level once (medium to hard), a name typed.
    Json r = run({"--name", "Tester"}, "lobby:1,lobby:1,lobby:2,lobby:0,x");
    EXPECT_EQ(r["ui"]["lobby_choice"]["rule_set"], "freestyle");
    EXPECT_EQ(r["ui"]["lobby_choice"]["bot_level"], "hard");
    EXPECT_EQ(r["ui"]["lobby_choice"]["name"], "Testerx");
    r = run({"--name", "Tester"}, "lobby:1,lobby:1,lobby:6,wait,wait,wait");
    EXPECT_FALSE(r["ui"]["lobby"].get<bool>()) << "Play the bot makes a room";
    EXPECT_EQ(r["ui"]["rule_set"], "freestyle");
}

} // namespace
} // namespace carrom::client
