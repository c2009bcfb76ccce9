// The desktop client's ratings against a real carrom-server --data (docs/client.md, "Ratings,
// leaderboard and my matches"): two carrom-bot processes with identities play a rated freestyle
// match, three established ICF ratings are written into the store, then carrom-client (as the
// identified player Asha, unattended, driven by --input) shows its lobby's rating line, the
// leaderboard, My matches, a match opened as a replay, and its seat's rating beside its name; a
// guest and a server without a store get their sentences.

#include "client_program.hpp"
#include "support/child_process.hpp"
#include "support/command_run.hpp"
#include "support/read_file.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using test_support::ServerProcess;
using test_support::TempDir;
using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

class RatingsViews : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir("carrom_ratings_views");
        ServerProcess::Options options;
        options.program = CARROM_SERVER_PATH;
        options.data = dir_->file("c.db");
        options.args = {"--time-scale", "25", "--log-level", "warn"};
        server_ = new ServerProcess(options);
        ASSERT_TRUE(server_->start()) << server_->log();
        play_rated_match();
        // Three established ICF ratings (deviation 80) for the leaderboard, written while the
        // server is stopped.
        server_->terminate();
        seed_established();
        ASSERT_TRUE(server_->restart()) << server_->log();
    }

    static void TearDownTestSuite() {
        delete server_;
        delete dir_;
    }

    // Asha creates a rated freestyle room, Ravi joins: two carrom-bot processes with keys.
    static void play_rated_match() {
        const std::string bot = CARROM_BOT_PATH;
        const std::string common = " --url " + server_->url() +
                                   " --strategy sampling --think-ms 50 --timeout 60 2>> " +
                                   dir_->file("bots.err");
        test_support::CommandRun creator;
        std::thread creator_thread([&] {
            creator = test_support::run_command(
                bot + " --identity " + dir_->file("asha.key") +
                " --name Asha --create --rated --rule-set freestyle --target-points 20" +
                " --shot-clock 0 --seed 3" + common);
        });
        std::string code;
        for (int i = 0; i < 200 && code.size() != 6; ++i) {
            std::this_thread::sleep_for(25ms);
            std::ifstream err(dir_->file("bots.err"));
            std::string word;
            while (err >> word) {
                if (word == "room" && err >> code) {
                    break;
                }
            }
        }
        const test_support::CommandRun joiner =
            test_support::run_command(bot + " --identity " + dir_->file("ravi.key") +
                                      " --name Ravi --join " + code + " --seed 4" + common);
        creator_thread.join();
        ASSERT_EQ(code.size(), 6U) << server_->log();
        ASSERT_EQ(creator.exit, 0) << creator.out;
        ASSERT_EQ(joiner.exit, 0) << joiner.out;
    }

    static void seed_established() {
        SQLite::Database db(dir_->file("c.db"), SQLite::OPEN_READWRITE);
        const std::vector<std::pair<std::string, double>> players{
            {"Kiran", 1712.4}, {"Meera", 1650.6}, {"Dev", 1602.2}};
        for (std::size_t i = 0; i < players.size(); ++i) {
            const std::string hash(32, static_cast<char>('A' + i)); // no key: never says hello
            std::string key = players[i].first;
            for (char& c : key) {
                c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            }
            SQLite::Statement player(db, "INSERT INTO identities VALUES (?, ?, ?, 0)");
            player.bind(1, hash.data(), 32);
            player.bind(2, players[i].first);
            player.bind(3, key);
            player.exec();
            SQLite::Statement rating(
                db, "INSERT INTO ratings VALUES (?, 'icf', ?, 80, 0.06, ?, ?, ?, 0, 0)");
            const int games = 30 - 6 * static_cast<int>(i);
            rating.bind(1, hash.data(), 32);
            rating.bind(2, players[i].second);
            rating.bind(3, games);
            rating.bind(4, games / 2);
            rating.bind(5, games - games / 2);
            rating.exec();
        }
    }

    // Runs carrom-client on `server` with args and --input `input`; its exit code must be 0.
    // Returns the screenshot report's "ui" "records" (or, with --final-state, {}).
    static Json run(const ServerProcess& server, std::vector<std::string> args,
                    const std::string& input) {
        const std::string report = dir_->file("report.json");
        std::remove(report.c_str());
        std::vector<std::string> all{
            "--url",     server.url(), "--mute", "--settings", dir_->file("settings.json"),
            "--timeout", "40"};
        const bool final_state = std::find(args.begin(), args.end(), "--final-state") != args.end();
        if (!final_state) {
            if (std::find(args.begin(), args.end(), "--frames") == args.end()) {
                all.insert(all.end(), {"--frames", "20"});
            }
            all.insert(all.end(), {"--screenshot", dir_->file("shot.png"), "--report", report});
        }
        all.insert(all.end(), args.begin(), args.end());
        if (!input.empty()) {
            all.insert(all.end(), {"--input", input});
        }
        ChildProcess client(client_argv(all), {client_asan_options()});
        const auto exit = client.wait_exit(Clock::now() + 50s);
        EXPECT_TRUE(exit && *exit == 0) << client.output();
        if (final_state) {
            return Json::object();
        }
        const Json j = Json::parse(test_support::read_file(report), nullptr, false);
        EXPECT_TRUE(j.is_object()) << client.output();
        return j.is_object() ? j["ui"]["records"] : Json::object();
    }

    static std::vector<std::string> as_asha() {
        return {"--name", "Asha", "--identity", dir_->file("asha.key")};
    }

    static Json player(const std::string& name) {
        return Json::parse(server_->get("/players/" + name).body, nullptr, false);
    }

    static TempDir* dir_;
    static ServerProcess* server_;
};

TempDir* RatingsViews::dir_ = nullptr;
ServerProcess* RatingsViews::server_ = nullptr;

TEST_F(RatingsViews, TheLobbyShowsTheRatingLine) {
    const Json asha = player("Asha");
    ASSERT_EQ(asha["ratings"].size(), 1U) << asha.dump();
    const Json r = run(*server_, as_asha(), "wait,wait");
    EXPECT_EQ(r["page"], "main");
    EXPECT_EQ(r["rating_line"],
              "Rating: freestyle " + asha["ratings"][0]["label"].get<std::string>());
    EXPECT_NE(r["rating_line"].get<std::string>().find('?'), std::string::npos)
        << "one game: provisional";
}

TEST_F(RatingsViews, TheLeaderboardListsTheEstablishedRatingsBestFirst) {
    Json r = run(*server_, as_asha(), "lobby:13,wait,wait");
    EXPECT_EQ(r["page"], "leaderboard");
    EXPECT_EQ(r["note"], "Established ratings in ICF rules, best first");
    EXPECT_EQ(r["rows"], Json::parse(R"([["1","Kiran","1712","30"],["2","Meera","1651","24"],
                                         ["3","Dev","1602","18"]])"));
    // Tab steps to the next rule set (classic) and reads again: nobody is established there.
    r = run(*server_, as_asha(), "F2,wait,Tab,wait,wait");
    EXPECT_EQ(r["rows"], Json::array());
    EXPECT_EQ(r["note"], "Nobody has an established classic rating yet (it takes about 10 rated "
                         "games).");
}

TEST_F(RatingsViews, MyMatchesListsTheRatedMatchWithItsResult) {
    const Json match = player("Asha")["matches"][0];
    const bool won = match["result"]["winner_team"] == 0;
    const Json r = run(*server_, as_asha(), "lobby:14,wait,wait");
    EXPECT_EQ(r["page"], "matches");
    ASSERT_EQ(r["rows"].size(), 1U) << r.dump();
    const Json row = r["rows"][0];
    EXPECT_EQ(row[0], "Ravi");
    EXPECT_EQ(row[1], "freestyle");
    const std::vector<int> scores = match["scores"].get<std::vector<int>>();
    EXPECT_EQ(row[2], std::string(won ? "won " : "lost ") + std::to_string(scores[0]) + " : " +
                          std::to_string(scores[1]));
    EXPECT_EQ(row[3].get<std::string>().size(), std::string("2026-11-28 17:40 UTC").size());
}

TEST_F(RatingsViews, AMatchOfMyMatchesOpensAsAReplay) {
    const Json match = player("Asha")["matches"][0];
    const std::string final_state = dir_->file("final.json");
    run(*server_,
        {"--name", "Asha", "--identity", dir_->file("asha.key"), "--final-state", final_state,
         "--replay-speed", "4"},
        "F3,wait,matches:1");
    const Json end = Json::parse(test_support::read_file(final_state), nullptr, false);
    ASSERT_TRUE(end.is_object());
    EXPECT_EQ(end["room"], match["room"]);
    EXPECT_EQ(end["scores"], match["scores"]);
    EXPECT_EQ(end["you"], -1) << "a replay watches";
}

TEST_F(RatingsViews, ASeatShowsItsPlayersRatingAndABotNone) {
    const std::string label = player("Asha")["ratings"][0]["label"];
    std::vector<std::string> args = as_asha();
    args.insert(args.end(), {"--vs-bot", "easy", "--rule-set", "freestyle"});
    const Json r = run(*server_, args, "");
    EXPECT_EQ(r["seat_ratings"], Json::array({label, ""}));
}

TEST_F(RatingsViews, AGuestHasNoRatingAndNoMatches) {
    const Json r = run(*server_, {"--name", "Guesty", "--identity", "none"}, "F3,wait,wait");
    EXPECT_EQ(r["rating_line"], "");
    EXPECT_EQ(r["note"], "No matches of Guesty on this server yet (only identified players' "
                         "matches are listed).");
}

TEST_F(RatingsViews, AServerWithoutAStoreSaysSoInTheLeaderboard) {
    ServerProcess bare({CARROM_SERVER_PATH, "none", {"--log-level", "warn"}, {}, 0});
    ASSERT_TRUE(bare.start()) << bare.log();
    const Json r = run(bare, {"--name", "Asha", "--identity", "none"}, "F2,wait,wait");
    EXPECT_EQ(r["page"], "leaderboard");
    EXPECT_EQ(r["note"], "This server keeps no ratings, so it has no leaderboard.");
    EXPECT_EQ(r["rows"], Json::array());
}

// Last: the match it plays changes both ratings. A quick match between identified players is
// rated: both seats show their ratings, and the room has no aim assist.
TEST_F(RatingsViews, ARatedQuickMatchShowsBothRatingsAndNoAimAssist) {
    const std::string asha = player("Asha")["ratings"][0]["label"];
    const std::string ravi = player("Ravi")["ratings"][0]["label"];
    // The bot plays random shots (it seldom pockets a coin) and the client none: the game is
    // on when the screenshot is taken, 3 input steps after the client's first turn at rest.
    ChildProcess bot({CARROM_BOT_PATH, "--identity", dir_->file("ravi.key"), "--name", "Ravi",
                      "--quick", "--rule-set", "freestyle", "--seed", "5", "--strategy", "random",
                      "--think-ms", "1000", "--timeout", "60", "--url", server_->url()});
    std::vector<std::string> args = as_asha();
    args.insert(args.end(), {"--quick", "--rule-set", "freestyle"});
    const Json r = run(*server_, args, "wait,wait,wait");
    bot.stop();
    const Json report = Json::parse(test_support::read_file(dir_->file("report.json")));
    // The one who waited first takes seat 0: whichever of the two connected first.
    EXPECT_TRUE(r["seat_ratings"] == Json::array({asha, ravi}) ||
                r["seat_ratings"] == Json::array({ravi, asha}))
        << r["seat_ratings"].dump() << "\n"
        << report["seats"].dump() << "\n"
        << report["ui"]["messages"].dump() << "\n"
        << bot.output();
    EXPECT_EQ(report["ui"]["aim_assist"], false);
}

} // namespace
} // namespace carrom::client
