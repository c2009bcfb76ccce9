// The desktop client's reading of GET /players/NAME and GET /leaderboard answers
// (player_record.hpp): the documented examples (docs/protocol.md), and bad answers (not JSON, a
// field missing or of another type, 404, 429, 503, 500, no answer) each as one sentence.
#include "carrom/client/player_record.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

const std::string kAsha =
    R"({"name":"Asha","created_ms":1700000000000,
 "ratings":[{"rule_set":"icf","rating":1532.4,"deviation":84.2,"volatility":0.05999,
             "provisional":false,"label":"1532","games":14,"wins":8,"losses":6,"draws":0,
             "last_game_ms":1700000900000}],
 "matches":[{"id":"k3j9x0a1b2c3d4e5","room":"K7M2QX","rule_set":"icf","players":["Asha","Ravi"],
             "teams":[0,1],"created_ms":1700000800000,"finished_ms":1700000900000,
             "result":{"winner_team":0,"reason":"target_points"},"scores":[25,11],
             "replay":"/matches/k3j9x0a1b2c3d4e5"}]})";

const std::string kBoard =
    R"({"rule_set":"icf","players":[{"rank":1,"name":"Asha","rating":1687.2,"deviation":61.0,
  "volatility":0.06,"provisional":false,"label":"1687","games":31,"wins":20,"losses":11,
  "draws":0,"last_game_ms":1700000900000}]})";

std::string player_problem(unsigned status, const std::string& body) {
    auto got = parse_player_answer("Asha", ApiAnswer{status, body, ""});
    return std::holds_alternative<std::string>(got) ? std::get<std::string>(got) : "(parsed)";
}

std::string board_problem(unsigned status, const std::string& body) {
    auto got = parse_leaderboard_answer(ApiAnswer{status, body, ""});
    return std::holds_alternative<std::string>(got) ? std::get<std::string>(got) : "(parsed)";
}

// kAsha with `from` replaced by `to` (once).
std::string asha_with(const std::string& from, const std::string& to) {
    std::string text = kAsha;
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(PlayerRecord, TheDocumentedExampleReadsWhole) {
    auto got = parse_player_answer("Asha", ApiAnswer{200, kAsha, ""});
    ASSERT_TRUE(std::holds_alternative<PlayerRecord>(got)) << std::get<std::string>(got);
    const PlayerRecord& r = std::get<PlayerRecord>(got);
    EXPECT_EQ(r.name, "Asha");
    ASSERT_EQ(r.ratings.size(), 1U);
    EXPECT_EQ(r.ratings[0].rule_set, "icf");
    EXPECT_DOUBLE_EQ(r.ratings[0].rating, 1532.4);
    EXPECT_FALSE(r.ratings[0].provisional);
    EXPECT_EQ(r.ratings[0].label, "1532");
    EXPECT_EQ(r.ratings[0].games, 14);
    EXPECT_EQ(r.ratings[0].wins, 8);
    ASSERT_EQ(r.matches.size(), 1U);
    const MatchEntry& m = r.matches[0];
    EXPECT_EQ(m.players, (std::vector<std::string>{"Asha", "Ravi"}));
    EXPECT_EQ(m.teams, (std::vector<int>{0, 1}));
    EXPECT_EQ(m.winner_team, 0);
    EXPECT_EQ(m.reason, "target_points");
    EXPECT_EQ(m.scores, (std::vector<int>{25, 11}));
    EXPECT_EQ(m.finished_ms, 1700000900000);
    EXPECT_EQ(m.replay, "/matches/k3j9x0a1b2c3d4e5");
}

TEST(PlayerRecord, AnUnknownPlayerIsOneWithoutRatings) {
    const std::string body =
        R"({"error":{"code":"unknown_player","message":"No identified player is called Guest."}})";
    auto got = parse_player_answer("Guest", ApiAnswer{404, body, ""});
    ASSERT_TRUE(std::holds_alternative<PlayerRecord>(got));
    EXPECT_EQ(std::get<PlayerRecord>(got).name, "Guest");
    EXPECT_TRUE(std::get<PlayerRecord>(got).ratings.empty());
}

TEST(PlayerRecord, AnUnfinishedMatchHasNoResult) {
    auto got = parse_player_answer(
        "Asha", ApiAnswer{200,
                          asha_with(R"("finished_ms":1700000900000,
             "result":{"winner_team":0,"reason":"target_points"},"scores":[25,11])",
                                    R"("finished_ms":null,"result":null,"scores":[])"),
                          ""});
    ASSERT_TRUE(std::holds_alternative<PlayerRecord>(got)) << std::get<std::string>(got);
    const MatchEntry& m = std::get<PlayerRecord>(got).matches[0];
    EXPECT_EQ(m.finished_ms, 0);
    EXPECT_FALSE(m.winner_team);
    EXPECT_EQ(m.reason, "");
}

TEST(PlayerRecord, ADrawHasANullWinner) {
    auto got = parse_player_answer(
        "Asha", ApiAnswer{200, asha_with(R"("winner_team":0)", R"("winner_team":null)"), ""});
    ASSERT_TRUE(std::holds_alternative<PlayerRecord>(got)) << std::get<std::string>(got);
    EXPECT_FALSE(std::get<PlayerRecord>(got).matches[0].winner_team);
    EXPECT_EQ(std::get<PlayerRecord>(got).matches[0].reason, "target_points");
}

TEST(PlayerRecord, OnlyA503StoreDisabledSaysTheServerKeepsNoPlayers) {
    const std::string disabled = R"({"error":{"code":"store_disabled","message":"No store."}})";
    EXPECT_TRUE(keeps_no_players(ApiAnswer{503, disabled, ""}));
    EXPECT_FALSE(keeps_no_players(ApiAnswer{503, R"({"error":{"code":"store_busy"}})", ""}));
    EXPECT_FALSE(keeps_no_players(ApiAnswer{500, disabled, ""}));
    EXPECT_FALSE(keeps_no_players(ApiAnswer{503, "store_disabled", ""}));
    EXPECT_FALSE(keeps_no_players(ApiAnswer{503, R"({"error":"store_disabled"})", ""}));
    EXPECT_FALSE(keeps_no_players(ApiAnswer{0, "", "The server did not answer."}));
}

TEST(PlayerRecord, NotJsonIsASentence) {
    EXPECT_EQ(player_problem(200, "<html>"),
              "The server sent the record of Asha in a form this client does not read (not "
              "JSON).");
}

TEST(PlayerRecord, AMissingFieldIsNamed) {
    EXPECT_EQ(player_problem(200, asha_with(R"("label":"1532",)", "")),
              "The server sent the record of Asha in a form this client does not read "
              "(ratings[0].label is missing).");
    EXPECT_EQ(player_problem(200, R"({"name":"Asha","ratings":[]})"),
              "The server sent the record of Asha in a form this client does not read (matches "
              "is missing).");
}

TEST(PlayerRecord, AWrongTypeIsNamed) {
    EXPECT_EQ(player_problem(200, asha_with(R"("games":14)", R"("games":"14")")),
              "The server sent the record of Asha in a form this client does not read "
              "(ratings[0].games must be a number).");
    EXPECT_EQ(player_problem(200, asha_with(R"("games":14)", R"("games":14.5)")),
              "The server sent the record of Asha in a form this client does not read "
              "(ratings[0].games must be an integer from 0 to 1000000000).");
    EXPECT_EQ(player_problem(200, asha_with(R"("provisional":false)", R"("provisional":0)")),
              "The server sent the record of Asha in a form this client does not read "
              "(ratings[0].provisional must be true or false).");
    EXPECT_EQ(player_problem(200, asha_with(R"(["Asha","Ravi"])", R"(["Asha",7])")),
              "The server sent the record of Asha in a form this client does not read "
              "(matches[0].players[1] must be a string).");
    EXPECT_EQ(player_problem(200, asha_with(R"("ratings":[)", R"("ratings":{"x":[)") + "}"),
              "The server sent the record of Asha in a form this client does not read (ratings "
              "must be a list).");
    EXPECT_EQ(player_problem(200, "[]"),
              "The server sent the record of Asha in a form this client does not read (name is "
              "missing).");
}

TEST(PlayerRecord, AReplayMustBeAMatchPath) {
    EXPECT_EQ(player_problem(200, asha_with("/matches/k3j9x0a1b2c3d4e5", "http://elsewhere/x")),
              "The server sent the record of Asha in a form this client does not read "
              "(matches[0].replay must be a path /matches/ID).");
}

TEST(PlayerRecord, TooManyRequestsIsASentence) {
    EXPECT_EQ(player_problem(429, R"({"error":{"code":"rate_limited","message":"Slow down."}})"),
              "The server has had too many requests from this address (429): try again in a "
              "moment.");
}

TEST(PlayerRecord, AServerWithoutAStoreSaysSo) {
    EXPECT_EQ(player_problem(503, R"({"error":{"code":"store_disabled","message":"x"}})"),
              "This server keeps no players or ratings (it runs without a store).");
    EXPECT_EQ(player_problem(503, R"({"error":{"code":"store_busy","message":"x"}})"),
              "The server's store is busy (503): try again in a moment.");
}

TEST(PlayerRecord, OtherStatusesGiveTheServersCodeAndMessage) {
    EXPECT_EQ(player_problem(500, R"({"error":{"code":"store_error","message":"disk I/O"}})"),
              "The server answered 500 store_error: disk I/O.");
    EXPECT_EQ(player_problem(400, R"({"error":{"code":"bad_player_name","message":"A name."}})"),
              "The server answered 400 bad_player_name: A name.");
    EXPECT_EQ(player_problem(404, "Not Found"), "The server answered 404.");
}

TEST(PlayerRecord, NoAnswerIsTheTransportsSentence) {
    auto got = parse_player_answer(
        "Asha", ApiAnswer{0, "", "Cannot connect to 127.0.0.1:1: connection refused."});
    EXPECT_EQ(std::get<std::string>(got), "Cannot connect to 127.0.0.1:1: connection refused.");
    EXPECT_EQ(player_problem(0, ""), "The server did not answer.");
}

TEST(Leaderboard, TheDocumentedExampleReadsWhole) {
    auto got = parse_leaderboard_answer(ApiAnswer{200, kBoard, ""});
    ASSERT_TRUE(std::holds_alternative<Leaderboard>(got)) << std::get<std::string>(got);
    const Leaderboard& b = std::get<Leaderboard>(got);
    EXPECT_EQ(b.rule_set, "icf");
    ASSERT_EQ(b.rows.size(), 1U);
    EXPECT_EQ(b.rows[0].rank, 1);
    EXPECT_EQ(b.rows[0].name, "Asha");
    EXPECT_EQ(b.rows[0].rating.label, "1687");
    EXPECT_EQ(b.rows[0].rating.rule_set, "icf");
    EXPECT_EQ(b.rows[0].rating.games, 31);
}

TEST(Leaderboard, AnEmptyBoardIsNoRows) {
    auto got = parse_leaderboard_answer(ApiAnswer{200, R"({"rule_set":"seed","players":[]})", ""});
    ASSERT_TRUE(std::holds_alternative<Leaderboard>(got));
    EXPECT_TRUE(std::get<Leaderboard>(got).rows.empty());
}

TEST(Leaderboard, BadRowsAreNamed) {
    std::string text = kBoard;
    text.replace(text.find(R"("rank":1)"), 8, R"("rank":-1)");
    EXPECT_EQ(board_problem(200, text),
              "The server sent the leaderboard in a form this client does not read "
              "(players[0].rank must be an integer from 0 to 1000000000).");
    EXPECT_EQ(board_problem(200, R"({"rule_set":"icf"})"),
              "The server sent the leaderboard in a form this client does not read (players is "
              "missing).");
    EXPECT_EQ(board_problem(200, R"({"rule_set":"icf","players":[{"rank":1}]})"),
              "The server sent the leaderboard in a form this client does not read "
              "(players[0].name is missing).");
    EXPECT_EQ(board_problem(200, "{"),
              "The server sent the leaderboard in a form this client does not read (not JSON).");
}

TEST(Leaderboard, ErrorStatusesAreSentences) {
    // The web page's words (rating_words.js) for these two.
    EXPECT_EQ(board_problem(429, ""),
              "Too many requests: try the leaderboard again in a few seconds.");
    EXPECT_EQ(board_problem(503, R"({"error":{"code":"store_disabled","message":"x"}})"),
              "This server keeps no ratings, so it has no leaderboard.");
    EXPECT_EQ(board_problem(400, R"({"error":{"code":"bad_query","message":"Unknown rule set."}})"),
              "The server answered 400 bad_query: Unknown rule set.");
}

TEST(PlayerPath, NamesArePercentEncoded) {
    EXPECT_EQ(player_path("Asha"), "/players/Asha");
    EXPECT_EQ(player_path("Ana B"), "/players/Ana%20B");
    EXPECT_EQ(player_path("Zo\xc3\xab/?#"), "/players/Zo%C3%AB%2F%3F%23");
    EXPECT_EQ(player_path("a-b.c_d~"), "/players/a-b.c_d~");
}

} // namespace
} // namespace carrom::client
