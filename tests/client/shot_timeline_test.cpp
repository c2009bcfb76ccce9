#include "carrom/client/shot_timeline.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

TEST(ShotTimeline, KnowsWhereEachPlacedShotStarts) {
    ShotTimeline t;
    EXPECT_EQ(t.start_of(3), std::nullopt);
    t.place(3, 12.5);
    EXPECT_EQ(t.start_of(3), 12.5);
    t.place(3, 13.0); // a prediction's start replaced by another
    EXPECT_EQ(t.start_of(3), 13.0);
    t.forget(3);
    EXPECT_EQ(t.start_of(3), std::nullopt);
}

TEST(ShotTimeline, KeepsTheHighestEightTurns) {
    ShotTimeline t;
    for (int turn = 10; turn >= 1; --turn) {
        t.place(turn, turn * 10.0);
    }
    EXPECT_EQ(t.start_of(1), std::nullopt);
    EXPECT_EQ(t.start_of(2), std::nullopt);
    EXPECT_EQ(t.start_of(3), 30.0);
    EXPECT_EQ(t.start_of(10), 100.0);
}

TEST(ShotTimeline, ATimeBelongsToTheShotThatStartedLastBeforeIt) {
    ShotTimeline t;
    EXPECT_EQ(t.shot_time(5.0).turn, -1);
    t.place(4, 10.0);
    t.place(5, 20.0);
    EXPECT_EQ(t.shot_time(9.0).turn, -1);
    EXPECT_EQ(t.shot_time(10.0).turn, 4);
    EXPECT_DOUBLE_EQ(t.shot_time(19.5).t_s, 9.5);
    EXPECT_EQ(t.shot_time(20.25).turn, 5);
    EXPECT_DOUBLE_EQ(t.shot_time(20.25).t_s, 0.25);
    t.clear();
    EXPECT_EQ(t.shot_time(20.25).turn, -1);
}

} // namespace
} // namespace carrom::client
