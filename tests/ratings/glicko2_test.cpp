// Glicko-2 against Glickman's worked example and the properties the server relies on.
#include "carrom/ratings/glicko2.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace carrom::ratings {
namespace {

const Rating kGlickmanPlayer{1500.0, 200.0, 0.06};

TEST(Glicko2, GlickmansWorkedExample) {
    const std::array<GameScore, 3> games{GameScore{Rating{1400.0, 30.0, 0.06}, 1.0},
                                         GameScore{Rating{1550.0, 100.0, 0.06}, 0.0},
                                         GameScore{Rating{1700.0, 300.0, 0.06}, 0.0}};
    const Rating after = Glicko2{}.rate(kGlickmanPlayer, games);
    EXPECT_NEAR(after.rating, 1464.05, 0.02);
    EXPECT_NEAR(after.deviation, 151.52, 0.01);
    EXPECT_NEAR(after.volatility, 0.05999, 1e-5);
}

TEST(Glicko2, IsDeterministic) {
    const std::array<GameScore, 1> game{GameScore{Rating{1612.0, 80.0, 0.059}, 1.0}};
    const Rating first = Glicko2{}.rate(kGlickmanPlayer, game);
    const Rating second = Glicko2{}.rate(kGlickmanPlayer, game);
    EXPECT_EQ(first, second);
}

TEST(Glicko2, WinRaisesLossLowersDrawBetweenEqualsKeepsRating) {
    const Rating player{};
    const std::array<GameScore, 1> win{GameScore{Rating{}, 1.0}};
    const std::array<GameScore, 1> loss{GameScore{Rating{}, 0.0}};
    const std::array<GameScore, 1> draw{GameScore{Rating{}, 0.5}};
    EXPECT_GT(Glicko2{}.rate(player, win).rating, 1500.0);
    EXPECT_LT(Glicko2{}.rate(player, loss).rating, 1500.0);
    EXPECT_NEAR(Glicko2{}.rate(player, draw).rating, 1500.0, 1e-9);
}

TEST(Glicko2, NewPlayersFirstWinAgainstANewPlayerIsWorthAbout160) {
    const std::array<GameScore, 1> win{GameScore{Rating{}, 1.0}};
    const Rating after = Glicko2{}.rate(Rating{}, win);
    EXPECT_NEAR(after.rating, 1662.3, 0.1);
    EXPECT_NEAR(after.deviation, 290.3, 0.1);
}

TEST(Glicko2, AnUpsetMovesMoreThanAnExpectedResult) {
    const Rating player{1500.0, 80.0, 0.06};
    const std::array<GameScore, 1> upset{GameScore{Rating{1900.0, 80.0, 0.06}, 1.0}};
    const std::array<GameScore, 1> expected{GameScore{Rating{1100.0, 80.0, 0.06}, 1.0}};
    EXPECT_GT(Glicko2{}.rate(player, upset).rating - 1500.0,
              5.0 * (Glicko2{}.rate(player, expected).rating - 1500.0));
}

TEST(Glicko2, GamesShrinkTheDeviation) {
    Rating player{};
    const std::array<GameScore, 1> win{GameScore{Rating{1500.0, 60.0, 0.06}, 1.0}};
    const std::array<GameScore, 1> loss{GameScore{Rating{1500.0, 60.0, 0.06}, 0.0}};
    for (int game = 0; game < 10; ++game) {
        const double before = player.deviation;
        player = Glicko2{}.rate(player, game % 2 == 0 ? std::span<const GameScore>(win)
                                                      : std::span<const GameScore>(loss));
        EXPECT_LT(player.deviation, before) << "game " << game;
    }
}

TEST(Glicko2, AnEmptyPeriodIsOneDayOfAgeing) {
    const Rating player{1720.0, 60.0, 0.06};
    EXPECT_EQ(Glicko2{}.rate(player, {}), Glicko2{}.age(player, 1));
}

TEST(Glicko2, AgeingGrowsOnlyTheDeviation) {
    const Rating player{1720.0, 60.0, 0.06};
    const Rating aged = Glicko2{}.age(player, 30);
    EXPECT_EQ(aged.rating, 1720.0);
    EXPECT_EQ(aged.volatility, 0.06);
    // sqrt((60/173.7178)^2 + 30 * 0.06^2) * 173.7178
    EXPECT_NEAR(aged.deviation, 82.820, 0.001);
}

TEST(Glicko2, NoIdlePeriodsChangeNothing) {
    const Rating player{1720.0, 60.0, 0.06};
    EXPECT_EQ(Glicko2{}.age(player, 0), player);
    EXPECT_EQ(Glicko2{}.age(player, -3), player);
}

TEST(Glicko2, AgeingStopsAtTheInitialDeviation) {
    const Rating aged = Glicko2{}.age(Rating{1720.0, 60.0, 0.06}, 100000);
    EXPECT_EQ(aged.deviation, kInitialDeviation);
    const std::array<GameScore, 1> win{GameScore{Rating{}, 1.0}};
    EXPECT_LE(Glicko2{}.rate(Rating{1500.0, 350.0, 0.5}, win).deviation, kInitialDeviation);
}

TEST(Glicko2, AnEstablishedRatingIsProvisionalAgainAfterAboutElevenWeeks) {
    const Rating established{1720.0, 60.0, 0.06};
    EXPECT_FALSE(is_provisional(Glicko2{}.age(established, 78)));
    EXPECT_TRUE(is_provisional(Glicko2{}.age(established, 79)));
}

TEST(Glicko2, ANewRatingIsEstablishedAfterSomeGamesAgainstEstablishedPlayers) {
    Rating player{};
    const std::array<GameScore, 1> win{GameScore{Rating{1500.0, 60.0, 0.06}, 1.0}};
    const std::array<GameScore, 1> loss{GameScore{Rating{1500.0, 60.0, 0.06}, 0.0}};
    int games = 0;
    while (is_provisional(player) && games < 100) {
        player = Glicko2{}.rate(player, games % 2 == 0 ? std::span<const GameScore>(win)
                                                       : std::span<const GameScore>(loss));
        ++games;
    }
    EXPECT_EQ(games, 10);
}

} // namespace
} // namespace carrom::ratings
