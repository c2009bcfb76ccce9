// The rating words both clients use (rating_words.hpp; the web page's rating_view.js has the same
// cases in tests/web/identity_test.mjs), the RatingBook's base and change, and the words of a
// row of "My matches" (match_line).
#include "carrom/client/rating_book.hpp"
#include "carrom/client/rating_words.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

RatingEntry rated_entry(const std::string& rule_set, double rating, const std::string& label,
                        int games) {
    RatingEntry r;
    r.rule_set = rule_set;
    r.rating = rating;
    r.label = label;
    r.games = games;
    return r;
}

const std::vector<RatingEntry> kBefore{rated_entry("icf", 1518.4, "1518", 12)};
const std::vector<RatingEntry> kAfter{rated_entry("icf", 1532.2, "1532", 13),
                                      rated_entry("freestyle", 1662.3, "1662?", 1)};

TEST(RatingWords, TheLobbyLineIsEmptyWithoutRatings) {
    EXPECT_EQ(rating_line(std::nullopt, {}), "");
}

TEST(RatingWords, TheLobbyLineWithoutAnEarlierReadShowsNoChange) {
    EXPECT_EQ(rating_line(std::nullopt, kBefore), "Rating: ICF 1518");
}

TEST(RatingWords, TheLobbyLineShowsTheChangeAndANewRuleSetsChangeFrom1500) {
    EXPECT_EQ(rating_line(kBefore, kAfter), "Rating: ICF 1532 (+14), freestyle 1662? (+162)");
}

TEST(RatingWords, NoChangeWithoutMoreGames) {
    EXPECT_EQ(rating_line(kAfter, kAfter), "Rating: ICF 1532, freestyle 1662?");
}

TEST(RatingWords, ALossShowsAMinusAndNoChangeAPlus) {
    EXPECT_EQ(rating_change_text(1662.3, 1600.6), "(-61)");
    EXPECT_EQ(rating_change_text(1500.4, 1499.6), "(+0)");
    EXPECT_EQ(rating_change_text(1337.7, 1338.2), "(+0)");
}

TEST(RatingWords, RuleSetsAreNamedAsTheLobbyNamesThem) {
    EXPECT_EQ(rating_rule_set_word("icf"), "ICF");
    EXPECT_EQ(rating_rule_set_word("seed"), "classic");
    EXPECT_EQ(rating_rule_set_word("freestyle"), "freestyle");
    EXPECT_EQ(rating_rule_set_word("discpool"), "disc pool");
    EXPECT_EQ(rating_rule_set_word("newrules"), "newrules");
}

TEST(RatingWords, ASeatShowsItsLabelAndAfterAGameTheChange) {
    EXPECT_EQ(seat_rating_text("icf", kBefore, std::nullopt), "1518");
    EXPECT_EQ(seat_rating_text("icf", kAfter, kBefore), "1532 (+14)");
    EXPECT_EQ(seat_rating_text("freestyle", kAfter, kBefore), "1662? (+162)");
    EXPECT_EQ(seat_rating_text("seed", kAfter, kBefore), "") << "no rating in that rule set";
}

TEST(RatingBook, AnUnreadNameShowsNothing) {
    const RatingBook book;
    EXPECT_EQ(book.lobby_line("Asha"), "");
    EXPECT_EQ(book.seat_text("Asha", "icf"), "");
    EXPECT_FALSE(book.has("Asha"));
}

TEST(RatingBook, TheChangeShowsAgainstTheBaseReadAsTheGameBegan) {
    RatingBook book;
    book.record(PlayerRecord{"Asha", kBefore, {}}, true);
    EXPECT_EQ(book.seat_text("Asha", "icf"), "1518");
    book.record(PlayerRecord{"Asha", kAfter, {}}, false);
    EXPECT_EQ(book.seat_text("Asha", "icf"), "1532 (+14)");
    EXPECT_EQ(book.lobby_line("Asha"), "Rating: ICF 1532 (+14), freestyle 1662? (+162)");
    book.game_starts({"Asha"}); // a rematch: the next change is against today's
    EXPECT_EQ(book.seat_text("Asha", "icf"), "1532");
}

TEST(RatingBook, ChangedIsMoreGamesThanTheBase) {
    RatingBook book;
    EXPECT_FALSE(book.changed("Asha", "icf")) << "nothing read";
    book.record(PlayerRecord{"Asha", kBefore, {}}, true);
    EXPECT_FALSE(book.changed("Asha", "icf"));
    book.record(PlayerRecord{"Asha", kAfter, {}}, false);
    EXPECT_TRUE(book.changed("Asha", "icf"));
    EXPECT_TRUE(book.changed("Asha", "freestyle")) << "a first rated game in a rule set";
    EXPECT_FALSE(book.changed("Asha", "seed"));
}

TEST(RatingBook, AGuestReadHasNoRating) {
    RatingBook book;
    book.record(PlayerRecord{"Guest", {}, {}}, true);
    EXPECT_TRUE(book.has("Guest"));
    EXPECT_EQ(book.seat_text("Guest", "icf"), "");
    EXPECT_EQ(book.lobby_line("Guest"), "");
}

MatchEntry singles_match(std::optional<int> winner, std::string reason) {
    MatchEntry m;
    m.id = "k3j9x0a1b2c3d4e5";
    m.rule_set = "icf";
    m.players = {"Asha", "Ravi"};
    m.teams = {0, 1};
    m.created_ms = 1700000800000;
    m.finished_ms = 1700000900000;
    m.winner_team = winner;
    m.reason = std::move(reason);
    m.scores = m.reason.empty() ? std::vector<int>{} : std::vector<int>{25, 11};
    m.replay = "/matches/" + m.id;
    return m;
}

TEST(MatchLine, AWinIsOurScoreFirst) {
    const MatchLine line = match_line(singles_match(0, "target_points"), "Asha");
    EXPECT_EQ(line.opponent, "Ravi");
    EXPECT_EQ(line.result, "won 25 : 11");
    EXPECT_EQ(line.date, "2023-11-14 22:28 UTC");
}

TEST(MatchLine, TheLoserSeesALossAndNamesCompareIgnoringCase) {
    const MatchLine line = match_line(singles_match(0, "target_points"), "ravi");
    EXPECT_EQ(line.opponent, "Asha");
    EXPECT_EQ(line.result, "lost 11 : 25");
}

TEST(MatchLine, ADrawAndAMatchWithoutResult) {
    EXPECT_EQ(match_line(singles_match(std::nullopt, "boards"), "Asha").result, "drawn 25 : 11");
    MatchEntry cut = singles_match(std::nullopt, "");
    cut.finished_ms = 0;
    const MatchLine line = match_line(cut, "Asha");
    EXPECT_EQ(line.result, "playing");
    EXPECT_EQ(line.date, "2023-11-14 22:26 UTC") << "the start's date without an end";
    cut.finished_ms = 1700000900000; // the room closed mid-game: an end without a result
    EXPECT_EQ(match_line(cut, "Asha").result, "unfinished");
}

TEST(MatchLine, DoublesNamesTheOtherThree) {
    MatchEntry m = singles_match(1, "target_points");
    m.players = {"Asha", "Ravi", "Ann", "Bo"};
    m.teams = {0, 1, 0, 1};
    const MatchLine line = match_line(m, "Asha");
    EXPECT_EQ(line.opponent, "Ravi, Ann & Bo");
    EXPECT_EQ(line.result, "lost 25 : 11");
}

} // namespace
} // namespace carrom::client
