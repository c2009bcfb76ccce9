// The quick-match rating window: the gap widens with time waited; the closest pair meets.
#include "carrom/ratings/rating_window.hpp"

#include <gtest/gtest.h>

#include <array>

namespace carrom::ratings {
namespace {

TEST(RatingWindow, GapWidensPerWholeSecond) {
    EXPECT_EQ(acceptable_gap(0.0), 100.0);
    EXPECT_EQ(acceptable_gap(0.99), 100.0);
    EXPECT_EQ(acceptable_gap(1.0), 125.0);
    EXPECT_EQ(acceptable_gap(20.0), 600.0);
    EXPECT_EQ(acceptable_gap(-5.0), 100.0);
}

TEST(RatingWindow, OfFourWaitingPlayersTheTwoClosestMeet) {
    const std::array<WaitingPlayer, 4> waiting{
        WaitingPlayer{1500.0, 3.0}, WaitingPlayer{1900.0, 3.0}, WaitingPlayer{1545.0, 0.0},
        WaitingPlayer{1530.0, 0.0}};
    const auto pair = closest_acceptable_pair(waiting);
    ASSERT_TRUE(pair.has_value());
    EXPECT_EQ(pair->first, 2U);
    EXPECT_EQ(pair->second, 3U);
}

TEST(RatingWindow, NoPairOutsideTheGapUntilTheLongerWaitWidensIt) {
    std::array<WaitingPlayer, 2> waiting{WaitingPlayer{1500.0, 0.0}, WaitingPlayer{1700.0, 0.0}};
    EXPECT_FALSE(closest_acceptable_pair(waiting).has_value());
    waiting[1].waited_s = 3.9; // 175 points
    EXPECT_FALSE(closest_acceptable_pair(waiting).has_value());
    waiting[1].waited_s = 4.0; // 200 points
    EXPECT_TRUE(closest_acceptable_pair(waiting).has_value());
}

TEST(RatingWindow, TiesGoToTheEarlierArrivals) {
    const std::array<WaitingPlayer, 4> waiting{
        WaitingPlayer{1500.0, 0.0}, WaitingPlayer{1550.0, 0.0}, WaitingPlayer{1800.0, 0.0},
        WaitingPlayer{1850.0, 0.0}};
    const auto pair = closest_acceptable_pair(waiting);
    ASSERT_TRUE(pair.has_value());
    EXPECT_EQ(pair->first, 0U);
    EXPECT_EQ(pair->second, 1U);
}

TEST(RatingWindow, FewerThanTwoWaitingMakeNoPair) {
    EXPECT_FALSE(closest_acceptable_pair({}).has_value());
    const std::array<WaitingPlayer, 1> one{WaitingPlayer{1500.0, 100.0}};
    EXPECT_FALSE(closest_acceptable_pair(one).has_value());
}

} // namespace
} // namespace carrom::ratings
