// A dropped player's seat: kept through the grace period for the same player to resume (mid-shot
// too), taken over by a newer session, and forfeited when the grace period ends.
#include "room/room_fixture.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace carrom::room {
namespace {

using testing::FakePeer;
using testing::RoomTest;

TEST_F(RoomTest, DropThenResumeMidShot) {
    seat_both();
    room_.shoot(*a_, break_shot(0));
    clock_.advance_ms(100);
    room_.tick();
    room_.disconnected(*b_);
    const auto dropped = a_->events<proto::PlayerDroppedEvent>();
    ASSERT_EQ(dropped.size(), 1U);
    EXPECT_EQ(dropped[0].seat, 1);
    EXPECT_EQ(dropped[0].grace_deadline_ms - dropped[0].server_time_ms, 60000);
    EXPECT_FALSE(a_->last_room_state().seats[1].connected);
    auto b2 = std::make_shared<FakePeer>(2, "Bo");
    ASSERT_FALSE(room_.resume(b2));
    ASSERT_EQ(a_->events<proto::PlayerReturnedEvent>().size(), 1U);
    EXPECT_EQ(b2->last_room_state().you, 1);
    EXPECT_EQ(b2->last_room_state().phase, proto::Phase::Moving);
    const auto snaps = b2->all<proto::Snapshot>();
    ASSERT_EQ(snaps.size(), 1U);
    EXPECT_TRUE(snaps[0].keyframe);
    EXPECT_EQ(snaps[0].seq, room_.seq());
    EXPECT_GT(snaps[0].t_s, 0.0);
    play_out();
    EXPECT_EQ(b2->all<proto::ShotResult>().size(), 1U);
    EXPECT_TRUE(b_->all<proto::ShotResult>().empty()); // the old connection hears nothing
}

TEST_F(RoomTest, ResumeReplacesAConnectedSession) {
    seat_both();
    auto b2 = std::make_shared<FakePeer>(2, "Bo");
    ASSERT_FALSE(room_.resume(b2));
    EXPECT_EQ(b_->last_error(), "replaced");
    EXPECT_EQ(b_->closed_with, proto::kCloseReplaced);
    room_.disconnected(*b_); // the old connection's close arrives later: ignored
    EXPECT_TRUE(a_->events<proto::PlayerDroppedEvent>().empty());
    EXPECT_TRUE(a_->last_room_state().seats[1].connected);
}

TEST_F(RoomTest, ResumeWithoutASeatIsABadToken) {
    seat_both();
    auto stranger = std::make_shared<FakePeer>(77, "X");
    const auto error = room_.resume(stranger);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "bad_token");
}

TEST_F(RoomTest, GraceExpiryForfeits) {
    seat_both();
    room_.disconnected(*b_);
    ASSERT_EQ(room_.next_wake_ms(), clock_.now_ms() + 60000);
    clock_.advance_ms(59999);
    room_.tick();
    EXPECT_TRUE(a_->events<proto::GameEndEvent>().empty());
    clock_.advance_ms(1);
    room_.tick();
    const auto ends = a_->events<proto::GameEndEvent>();
    ASSERT_EQ(ends.size(), 1U);
    EXPECT_EQ(ends[0].winner, 0);
    EXPECT_EQ(ends[0].reason, "forfeit");
    EXPECT_EQ(room_.phase(), proto::Phase::GameOver);
    EXPECT_FALSE(a_->last_room_state().seats[1].occupied);
    EXPECT_EQ(counters_.matches_finished_total.load(), 1);
}

} // namespace
} // namespace carrom::room
