#include "carrom/client/game_over_text.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

// Ana (seat 0) against a bot (seat 1), seen from `you`, after a game_end.
MatchView ended(int you, int winner, std::string reason, std::vector<int> scores,
                proto::RuleSet rules = proto::RuleSet::Icf) {
    MatchView v;
    v.in_room = true;
    v.you = you;
    v.rule_set = rules;
    v.options = {25, 8, 20.0};
    v.seats.resize(2);
    v.seats[0].occupied = true;
    v.seats[0].name = "Ana";
    v.seats[1].occupied = true;
    v.seats[1].name = "Bot (medium)";
    v.phase = proto::Phase::GameOver;
    v.winner = winner;
    v.result = GameResult{winner, std::move(reason), std::move(scores), {}};
    return v;
}

TEST(GameOverText, ThreeMissedShotClocksAreNamed) {
    // The case of issue 19: the player let the clock run out three times against a bot.
    const GameOverText t = game_over_text(ended(0, 1, "clock", {0, 0}), false);
    EXPECT_EQ(t.title, "You lost");
    EXPECT_EQ(t.reason, "You let the shot clock run out three times in a row.");
    EXPECT_EQ(t.score, "Final score: Ana 0, Bot (medium) 0");
    EXPECT_TRUE(t.can_rematch);
    EXPECT_EQ(t.waiting, "");
    const GameOverText other = game_over_text(ended(0, 0, "clock", {3, 1}), false);
    EXPECT_EQ(other.title, "You won!");
    EXPECT_EQ(other.reason, "Bot (medium) let the shot clock run out three times in a row.");
}

TEST(GameOverText, ScoreAndBoards) {
    const GameOverText score = game_over_text(ended(0, 0, "score", {27, 12}), false);
    EXPECT_EQ(score.title, "You won!");
    EXPECT_EQ(score.reason, "You reached 25 points.");
    EXPECT_EQ(score.score, "Final score: Ana 27, Bot (medium) 12");
    EXPECT_EQ(game_over_text(ended(0, 1, "score", {12, 25}), false).reason,
              "Bot (medium) reached 25 points.");
    EXPECT_EQ(game_over_text(ended(0, 1, "boards", {10, 14}), false).reason,
              "All 8 boards are played and Bot (medium) has more points.");
    EXPECT_EQ(game_over_text(ended(0, 0, "boards", {14, 10}), false).reason,
              "All 8 boards are played and you have more points.");
    MatchView one = ended(0, -1, "boards", {3, 3});
    one.options.boards = 1;
    const GameOverText draw = game_over_text(one, false);
    EXPECT_EQ(draw.title, "A draw");
    EXPECT_EQ(draw.reason, "The board is played and the scores are level.");
}

TEST(GameOverText, ClearedSaysWhatTheRuleSetEndsOn) {
    EXPECT_EQ(game_over_text(ended(0, 1, "cleared", {4, 6}, proto::RuleSet::Seed), false).reason,
              "A colour is off the board and Bot (medium) has more points.");
    EXPECT_EQ(
        game_over_text(ended(0, -1, "cleared", {90, 90}, proto::RuleSet::Freestyle), false).reason,
        "No coins are left on the board and the scores are level.");
    EXPECT_EQ(
        game_over_text(ended(0, 0, "cleared", {9, 5}, proto::RuleSet::DiscPool), false).reason,
        "All your coins are off the board.");
    EXPECT_EQ(
        game_over_text(ended(0, 1, "cleared", {5, 9}, proto::RuleSet::DiscPool), false).reason,
        "All of Bot (medium)'s coins are off the board.");
}

TEST(GameOverText, ForfeitAndLeavingNameWhoWentAway) {
    EXPECT_EQ(game_over_text(ended(0, 0, "forfeit", {5, 3}), false).reason,
              "Bot (medium) lost the connection and did not come back in time.");
    EXPECT_EQ(game_over_text(ended(1, 1, "left", {5, 3}), false).reason, "Ana left the game.");
    EXPECT_EQ(game_over_text(ended(1, 1, "left", {5, 3}), false).title, "You won!");
}

TEST(GameOverText, OurSeatComesFirstInTheScore) {
    EXPECT_EQ(game_over_text(ended(1, 1, "score", {12, 25}), false).score,
              "Final score: Bot (medium) 25, Ana 12");
}

TEST(GameOverText, ASpectatorSeesTheWinnerAndNoRematch) {
    const GameOverText t = game_over_text(ended(-1, 0, "score", {25, 3}), false);
    EXPECT_EQ(t.title, "Ana won");
    EXPECT_EQ(t.reason, "Ana reached 25 points.");
    EXPECT_EQ(t.score, "Final score: Ana 25, Bot (medium) 3");
    EXPECT_FALSE(t.can_rematch);
    EXPECT_EQ(game_over_text(ended(-1, 0, "score", {25, 3}), true).waiting, "");
}

TEST(GameOverText, AfterAskingForARematchItWaitsForTheOpponent) {
    const GameOverText t = game_over_text(ended(0, 1, "clock", {0, 0}), true);
    EXPECT_FALSE(t.can_rematch);
    EXPECT_EQ(t.waiting, "Waiting for Bot (medium) to agree to a rematch");
    MatchView alone = ended(0, 0, "left", {2, 0});
    alone.seats[1] = SeatView{};
    EXPECT_EQ(game_over_text(alone, true).waiting, "Your opponent left the room: no rematch");
}

TEST(GameOverText, NoRematchIsOfferedOnceTheOpponentLeft) {
    MatchView v = ended(0, 0, "left", {2, 0});
    v.result->names = {"Ana", "Bot (medium)"};
    v.seats[1] = SeatView{};
    const GameOverText t = game_over_text(v, false);
    EXPECT_FALSE(t.can_rematch);
    EXPECT_TRUE(t.opponent_left);
    EXPECT_EQ(t.waiting, "Your opponent left the room: no rematch");
    EXPECT_EQ(t.title, "You won!");
    EXPECT_EQ(t.reason, "Bot (medium) left the game.");
    // The game_end comes before the room state that frees the seat: no rematch already.
    const GameOverText early = game_over_text(ended(0, 0, "left", {2, 0}), false);
    EXPECT_FALSE(early.can_rematch);
    EXPECT_TRUE(early.opponent_left);
    const GameOverText full = game_over_text(ended(0, 0, "score", {25, 3}), false);
    EXPECT_TRUE(full.can_rematch);
    EXPECT_FALSE(full.opponent_left);
}

TEST(GameOverText, NamesStayWhenTheOpponentLeavesAfterTheEnd) {
    MatchView v = ended(0, 1, "clock", {0, 0});
    v.result->names = {"Ana", "Ben"};
    v.seats[1] = SeatView{}; // Ben went back to the lobby
    const GameOverText t = game_over_text(v, false);
    EXPECT_EQ(t.score, "Final score: Ana 0, Ben 0");
    EXPECT_EQ(player_name_at_end(v, 1), "Ben");
    EXPECT_EQ(seat_name(v, 1), "Seat 2");
}

TEST(GameOverText, UnknownOrMissingReasons) {
    // Came in after the end: the room state says who won but not why.
    EXPECT_EQ(game_over_text(ended(0, 1, "", {3, 25}), false).reason, "The game is over.");
    EXPECT_EQ(game_over_text(ended(0, 1, "comet", {3, 25}), false).reason,
              "The game is over (comet).");
    MatchView none = ended(0, 1, "", {});
    none.result.reset();
    none.seats[0].score = 4;
    none.seats[1].score = 25;
    const GameOverText t = game_over_text(none, false);
    EXPECT_EQ(t.title, "You lost");
    EXPECT_EQ(t.score, "Final score: Ana 4, Bot (medium) 25");
}

// Doubles: Asha (0) and Ravi (2) against Ben (1) and a bot (3); winner is a team.
MatchView doubles_ended(int you, int winner, std::string reason, std::vector<int> scores) {
    MatchView v = ended(you, winner, std::move(reason), std::move(scores));
    v.seats.resize(4);
    const char* names[] = {"Asha", "Ben", "Ravi", "Bot (easy)"};
    for (std::size_t i = 0; i < 4; ++i) {
        v.seats[i] = SeatView{};
        v.seats[i].occupied = true;
        v.seats[i].name = names[i];
    }
    v.seats[3].bot = true;
    return v;
}

TEST(GameOverText, DoublesNamesTheWinningTeam) {
    const GameOverText spectator =
        game_over_text(doubles_ended(-1, 0, "score", {25, 12, 25, 12}), false);
    EXPECT_EQ(spectator.title, "Asha & Ravi win");
    EXPECT_EQ(spectator.reason, "Asha & Ravi reached 25 points.");
    EXPECT_EQ(spectator.score, "Final score: Asha & Ravi 25, Ben & Bot (easy) 12");
    const GameOverText partner =
        game_over_text(doubles_ended(2, 0, "boards", {14, 10, 14, 10}), false);
    EXPECT_EQ(partner.title, "You & Asha win");
    EXPECT_EQ(partner.reason, "All 8 boards are played and you & Asha have more points.");
    const GameOverText loser =
        game_over_text(doubles_ended(1, 0, "score", {25, 12, 25, 12}), false);
    EXPECT_EQ(loser.title, "Asha & Ravi win");
    EXPECT_EQ(loser.score, "Final score: Ben & Bot (easy) 12, Asha & Ravi 25");
    EXPECT_EQ(game_over_text(doubles_ended(0, 1, "clock", {0, 0, 0, 0}), false).reason,
              "A player of your team let the shot clock run out three times in a row.");
    EXPECT_EQ(game_over_text(doubles_ended(0, 0, "left", {3, 0, 3, 0}), false).reason,
              "A player of Ben & Bot (easy) left the game.");
}

TEST(GameOverText, DoublesRematchWaitsForTheOtherHumans) {
    EXPECT_EQ(game_over_text(doubles_ended(0, 0, "score", {25, 1, 25, 1}), true).waiting,
              "Waiting for the other players to agree to a rematch");
    MatchView bots = doubles_ended(0, 0, "score", {25, 1, 25, 1});
    bots.seats[1].bot = true;
    bots.seats[2].bot = true; // only server bots besides us: they agree at once
    EXPECT_EQ(game_over_text(bots, true).waiting,
              "Waiting for the other players to agree to a rematch");
    MatchView one = doubles_ended(0, 0, "score", {25, 1, 25, 1});
    one.seats[2].bot = true;
    EXPECT_EQ(game_over_text(one, true).waiting, "Waiting for Ben to agree to a rematch");
}

} // namespace
} // namespace carrom::client
