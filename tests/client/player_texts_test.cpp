// What a newcomer reads in carrom-client, under Xvfb against a real carrom-server (the words are
// the web page's too: tests/web/texts_pages.mjs): three missed shot clocks against a server bot
// (each miss says how many more lose, in the warning colour; the game over from the loser's side
// with the final score), an opponent who leaves (the forfeit line, no rematch offered), the card
// between two boards, doubles bots with names of their own, and the empty name in plain words.
// The client writes what it showed (--final-state, --report: its lines and panels' texts).

#include "client_program.hpp"
#include "support/child_process.hpp"
#include "support/temp_dir.hpp"

#include "carrom/net/connection.hpp"
#include "carrom/proto/version.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

// A carrom-server on an ephemeral port; url() is empty if it did not start.
class TextsServer {
public:
    explicit TextsServer(std::vector<std::string> args) : process_(argv(std::move(args))) {
        const std::string prefix = "listening on 127.0.0.1:";
        if (const auto line =
                process_.wait_line(ChildProcess::Stream::Out, prefix, Clock::now() + 15s)) {
            url_ = "ws://127.0.0.1:" + line->substr(prefix.size());
        }
    }
    const std::string& url() const { return url_; }

private:
    static std::vector<std::string> argv(std::vector<std::string> args) {
        std::vector<std::string> out{CARROM_SERVER_PATH, "--host", "127.0.0.1", "--port", "0",
                                     "--log-level",      "warn",   "--data",    "none"};
        out.insert(out.end(), args.begin(), args.end());
        return out;
    }
    ChildProcess process_;
    std::string url_;
};

// carrom-client with args; its exit code and the JSON it wrote to `json` (null if none).
struct TextsRun {
    int exit = -1;
    nlohmann::json written;
    std::string log;
};

TextsRun run_texts_client(const std::vector<std::string>& args, const std::string& json,
                          std::chrono::seconds limit) {
    TextsRun r;
    ChildProcess client(client_argv(args), {client_asan_options()});
    r.exit = client.wait_exit(Clock::now() + limit).value_or(-1);
    for (const auto stream : {ChildProcess::Stream::Out, ChildProcess::Stream::Err}) {
        for (const std::string& line : client.lines(stream)) {
            r.log += line + "\n";
        }
    }
    std::ifstream in(json);
    r.written = in ? nlohmann::json::parse(in, nullptr, false) : nlohmann::json();
    return r;
}

// The tone of the line said with this text, or "" if none was.
std::string tone_of(const nlohmann::json& said, const std::string& text) {
    for (const auto& line : said) {
        if (line.at("text") == text) {
            return line.at("tone").get<std::string>();
        }
    }
    return "";
}

std::string said_lines(const nlohmann::json& said) {
    std::string out;
    for (const auto& line : said) {
        out +=
            line.at("text").get<std::string>() + " [" + line.at("tone").get<std::string>() + "]\n";
    }
    return out;
}

TEST(PlayerTexts, ThreeMissedClocksAgainstABotAreCountedAndLoseTheGame) {
    TextsServer server({"--shot-clock", "1", "--bot-shot-clock", "1", "--time-scale", "8",
                        "--bot-think-ms", "50"});
    ASSERT_FALSE(server.url().empty());
    test_support::TempDir dir("carrom-texts-clock");
    const std::string json = dir.file("final.json");
    const TextsRun r = run_texts_client({"--url", server.url(), "--name", "Asha", "--vs-bot",
                                         "easy", "--mute", "--width", "700", "--height", "700",
                                         "--final-state", json, "--timeout", "50"},
                                        json, 60s);
    ASSERT_EQ(r.exit, 0) << r.log;
    const nlohmann::json& said = r.written.at("said");
    const std::string miss = "Foul by Asha: The shot clock ran out; the turn passes. ";
    EXPECT_EQ(tone_of(said, miss + "2 more missed turns in a row lose the game."), "foul")
        << said_lines(said);
    EXPECT_EQ(tone_of(said, miss + "One more missed turn in a row loses the game."), "foul");
    EXPECT_EQ(tone_of(said, "Foul by Asha: Too many turns were missed in a row: the game is lost."),
              "foul");
    for (const auto& line : said) {
        EXPECT_FALSE(line.at("tone") == "good" &&
                     line.at("text").get<std::string>().find("Foul") != std::string::npos);
    }
    const nlohmann::json& over = r.written.at("game_over");
    EXPECT_EQ(over.at("title"), "You lost");
    EXPECT_EQ(over.at("reason"), "You let the shot clock run out three times in a row.");
    EXPECT_TRUE(std::regex_match(over.at("score").get<std::string>(),
                                 std::regex(R"(Final score: Asha 0, Bot \(easy\) \d+)")))
        << over.at("score");
    EXPECT_TRUE(over.at("can_rematch").get<bool>()); // a bot always agrees
}

TEST(PlayerTexts, AnOpponentWhoLeavesIsNamedAndNoRematchIsOffered) {
    TextsServer server({"--shot-clock", "0", "--no-bots"});
    ASSERT_FALSE(server.url().empty());
    auto ravi = net::Connection::open(server.url());
    ravi->send(proto::Hello{proto::kProtocolVersion, "Ravi", std::nullopt});
    std::string code;
    bool left = false;
    test_support::TempDir dir("carrom-texts-leave");
    const std::string json = dir.file("final.json");
    const auto deadline = Clock::now() + 40s;
    while (code.empty() && Clock::now() < deadline) {
        ravi->wait(50ms);
        for (const proto::ServerMessage& m : ravi->poll()) {
            if (std::holds_alternative<proto::Welcome>(m)) {
                ravi->send(proto::CreateRoom{});
            } else if (const auto* room = std::get_if<proto::RoomState>(&m)) {
                code = room->code;
            }
        }
    }
    ASSERT_FALSE(code.empty());
    ChildProcess client(
        client_argv({"--url", server.url(), "--name", "Asha", "--join", code, "--mute", "--width",
                     "700", "--height", "700", "--final-state", json, "--timeout", "30"}),
        {client_asan_options()});
    std::optional<int> exit;
    while (!exit && Clock::now() < deadline) {
        ravi->wait(20ms);
        for (const proto::ServerMessage& m : ravi->poll()) {
            const auto* room = std::get_if<proto::RoomState>(&m);
            if (!left && room != nullptr && room->seats.size() == 2 && room->seats[1].occupied) {
                ravi->send(proto::Leave{}); // Asha took her seat: Ravi leaves the game
                left = true;
            }
        }
        exit = client.wait_exit(Clock::now() + 20ms);
    }
    ASSERT_EQ(exit.value_or(-1), 0);
    std::ifstream in(json);
    const nlohmann::json written = nlohmann::json::parse(in, nullptr, false);
    const nlohmann::json& said = written.at("said");
    EXPECT_EQ(tone_of(said, "Ravi left the match: you win by forfeit"), "good") << said_lines(said);
    for (const auto& line : said) {
        EXPECT_EQ(line.at("text").get<std::string>().find("A player forfeited"), std::string::npos);
    }
    const nlohmann::json& over = written.at("game_over");
    EXPECT_EQ(over.at("title"), "You won!");
    EXPECT_EQ(over.at("reason"), "Ravi left the game.");
    EXPECT_FALSE(over.at("can_rematch").get<bool>());
    EXPECT_TRUE(over.at("opponent_left").get<bool>());
    EXPECT_EQ(over.at("waiting"), "Your opponent left the room: no rematch");
}

TEST(PlayerTexts, TheCardBetweenTwoBoardsNamesTheWinnerPointsAndNewColour) {
    TextsServer server({"--shot-clock", "0", "--time-scale", "25"});
    ASSERT_FALSE(server.url().empty());
    ChildProcess bot({CARROM_BOT_PATH, "--url",    server.url(),      "--name",
                      "Ravi",          "--create", "--rule-set",      "icf",
                      "--boards",      "2",        "--target-points", "99",
                      "--strategy",    "greedy",   "--level",         "hard",
                      "--think-ms",    "20",       "--timeout",       "150"});
    const std::string prefix = "room ";
    const auto line = bot.wait_line(ChildProcess::Stream::Err, prefix, Clock::now() + 15s);
    ASSERT_TRUE(line);
    test_support::TempDir dir("carrom-texts-board");
    const std::string png = dir.file("card.png");
    const std::string json = dir.file("card.json");
    const TextsRun r = run_texts_client(
        {"--url",      server.url(),   "--name", "Asha",     "--join", line->substr(prefix.size()),
         "--autoplay", "hard",         "--mute", "--width",  "700",    "--height",
         "700",        "--screenshot", png,      "--report", json,     "--board-summary",
         "--timeout",  "140"},
        json, 150s);
    ASSERT_EQ(r.exit, 0) << r.log;
    const nlohmann::json& card = r.written.at("board_summary");
    ASSERT_TRUE(card.is_object()) << r.written.dump();
    EXPECT_TRUE(
        std::regex_match(card.at("title").get<std::string>(), std::regex("(You|Ravi) won board 1")))
        << card.at("title");
    EXPECT_TRUE(std::regex_match(card.at("points").get<std::string>(),
                                 std::regex(R"(\+\d+ points?\. Score: you \d+, Ravi \d+)")))
        << card.at("points");
    EXPECT_TRUE(std::regex_match(card.at("colours").get<std::string>(),
                                 std::regex("Board 2: you play (white|black)")))
        << card.at("colours");
}

TEST(PlayerTexts, DoublesBotsHaveNamesOfTheirOwn) {
    TextsServer server({"--shot-clock", "0", "--time-scale", "25", "--bot-think-ms", "20"});
    ASSERT_FALSE(server.url().empty());
    test_support::TempDir dir("carrom-texts-doubles");
    const std::string png = dir.file("doubles.png");
    const std::string json = dir.file("doubles.json");
    const TextsRun r = run_texts_client(
        {"--url", server.url(), "--name",  "Asha",     "--vs-bot", "easy",      "--seats",
         "4",     "--mute",     "--width", "700",      "--height", "700",       "--screenshot",
         png,     "--report",   json,      "--frames", "30",       "--timeout", "30"},
        json, 40s);
    ASSERT_EQ(r.exit, 0) << r.log;
    const nlohmann::json& names = r.written.at("names");
    ASSERT_EQ(names.size(), 4u) << r.written.dump();
    std::set<std::string> bots;
    for (std::size_t seat = 1; seat < 4; ++seat) {
        bots.insert(names[seat].get<std::string>());
        EXPECT_TRUE(std::regex_match(names[seat].get<std::string>(),
                                     std::regex(R"(Bot [A-Z][a-z]+ \(easy\))")))
            << names[seat];
    }
    EXPECT_EQ(bots.size(), 3u);
}

TEST(PlayerTexts, AnEmptyNameIsRefusedInPlainWords) {
    const TextsRun r = run_texts_client({"--name", " ", "--url", "ws://127.0.0.1:9"}, {}, 20s);
    EXPECT_EQ(r.exit, 2);
    EXPECT_NE(r.log.find("--name: type a name of 1 to 24 letters (accented letters count twice), "
                         "not only spaces"),
              std::string::npos)
        << r.log;
    EXPECT_EQ(r.log.find("bytes"), std::string::npos) << r.log;
}

} // namespace
} // namespace carrom::client
