// A stroke whose journal entry waits for the sink longer than store_pause_after_ms pauses the
// match: `paused` to every member once, `resumed` when the entry is written and before anything
// of the stroke streams; the shot clock does not run meanwhile (docs/cluster.md, "The database
// down").
#include "room/recording_journal.hpp"
#include "room/room_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <variant>

namespace carrom::room {
namespace {

using testing::RecordingJournal;
using testing::RoomTest;

constexpr double kShotClockS = 20.0;

class RoomStorePauseTest : public RoomTest {
protected:
    static RoomConfig store_pause_config() {
        RoomConfig c = config();
        c.rules.shot_clock_s = kShotClockS;
        return c;
    }

    // Both players and a spectator in, then seat 0 breaks: its entry waits for the sink.
    void SetUp() override {
        ASSERT_FALSE(paused_room_.join(a_, proto::Role::Player));
        ASSERT_FALSE(paused_room_.join(watcher_, proto::Role::Spectator));
        ASSERT_FALSE(paused_room_.join(b_, proto::Role::Player));
        for (auto* peer : {a_.get(), b_.get(), watcher_.get()}) {
            peer->clear();
        }
        paused_room_.shoot(*a_, break_shot(0));
    }

    void confirm_and_play_out() {
        sink_.confirm_all(paused_room_);
        while (paused_room_.phase() == proto::Phase::Moving) {
            clock_.set_ms(std::max(clock_.now_ms(), *paused_room_.next_wake_ms()));
            paused_room_.tick();
        }
    }

    RecordingJournal sink_;
    Room paused_room_{"PAUSED", store_pause_config(), clock_, counters_, nullptr, &sink_};
};

TEST_F(RoomStorePauseTest, AWaitPastTheThresholdPausesOnceAndResumesBeforeTheStrokeStreams) {
    ASSERT_EQ(sink_.waiting.size(), 1U);
    const std::int64_t shot_ms = clock_.now_ms();
    EXPECT_EQ(paused_room_.next_wake_ms(), shot_ms + kStorePauseAfterMs);
    clock_.advance_ms(kStorePauseAfterMs - 1);
    paused_room_.tick();
    EXPECT_TRUE(b_->events<proto::PausedEvent>().empty());
    clock_.advance_ms(1);
    paused_room_.tick();
    for (auto* peer : {a_.get(), b_.get(), watcher_.get()}) {
        const auto paused = peer->events<proto::PausedEvent>();
        ASSERT_EQ(paused.size(), 1U);
        EXPECT_EQ(paused[0].reason, "store");
        EXPECT_EQ(paused[0].message,
                  "The server cannot save the last stroke because its database does not answer; "
                  "the match goes on when it is back.");
        EXPECT_TRUE(peer->all<proto::Snapshot>().empty());
    }
    EXPECT_FALSE(paused_room_.next_wake_ms()); // only the sink's answer wakes the room now
    clock_.advance_ms(30000);
    paused_room_.tick();
    EXPECT_EQ(b_->events<proto::PausedEvent>().size(), 1U); // once per wait
    paused_room_.shoot(*a_, break_shot(0));                 // nothing played twice
    EXPECT_EQ(a_->last_error(), "in_motion");
    paused_room_.shoot(*b_, break_shot(1));
    EXPECT_FALSE(b_->error_codes().empty());

    sink_.confirm_all(paused_room_);
    for (auto* peer : {a_.get(), b_.get(), watcher_.get()}) {
        const auto& received = peer->received;
        const auto is_resumed = [](const proto::ServerMessage& m) {
            const auto* e = std::get_if<proto::Event>(&m);
            return e != nullptr && std::holds_alternative<proto::ResumedEvent>(*e);
        };
        const auto resumed = std::find_if(received.begin(), received.end(), is_resumed);
        const auto snapshot = std::find_if(received.begin(), received.end(), [](const auto& m) {
            return std::holds_alternative<proto::Snapshot>(m);
        });
        ASSERT_NE(resumed, received.end());
        EXPECT_EQ(std::count_if(received.begin(), received.end(), is_resumed), 1);
        ASSERT_NE(snapshot, received.end());
        EXPECT_LT(resumed - received.begin(), snapshot - received.begin());
    }
}

TEST_F(RoomStorePauseTest, AMemberWhoEntersDuringThePauseHearsOfIt) {
    clock_.advance_ms(kStorePauseAfterMs);
    paused_room_.tick();
    auto late = std::make_shared<testing::FakePeer>(4, "Dee");
    ASSERT_FALSE(paused_room_.join(late, proto::Role::Spectator));
    ASSERT_EQ(late->events<proto::PausedEvent>().size(), 1U);
    EXPECT_EQ(late->events<proto::PausedEvent>()[0], b_->events<proto::PausedEvent>()[0]);
    EXPECT_TRUE(std::holds_alternative<proto::Snapshot>(late->received.at(1))); // the keyframe
    paused_room_.disconnected(*b_);
    auto back = std::make_shared<testing::FakePeer>(2, "Bo");
    ASSERT_FALSE(paused_room_.resume(back));
    EXPECT_EQ(back->events<proto::PausedEvent>().size(), 1U);
    sink_.confirm_all(paused_room_);
    EXPECT_EQ(late->events<proto::ResumedEvent>().size(), 1U);
    EXPECT_EQ(back->events<proto::ResumedEvent>().size(), 1U);
}

TEST_F(RoomStorePauseTest, APlayerWhoLeavesDuringThePauseEndsItAndTheGame) {
    clock_.advance_ms(kStorePauseAfterMs);
    paused_room_.tick();
    paused_room_.leave(*b_);
    EXPECT_EQ(a_->events<proto::ResumedEvent>().size(), 1U);
    ASSERT_EQ(a_->events<proto::GameEndEvent>().size(), 1U);
    EXPECT_EQ(a_->events<proto::GameEndEvent>()[0].reason, "left");
    sink_.confirm_all(paused_room_); // the late answer changes nothing
    EXPECT_EQ(a_->events<proto::ResumedEvent>().size(), 1U);
}

TEST_F(RoomStorePauseTest, AWriteWithinTheThresholdPausesNothing) {
    clock_.advance_ms(kStorePauseAfterMs - 1);
    paused_room_.tick();
    confirm_and_play_out();
    EXPECT_TRUE(b_->events<proto::PausedEvent>().empty());
    EXPECT_TRUE(b_->events<proto::ResumedEvent>().empty());
    EXPECT_EQ(b_->all<proto::ShotResult>().size(), 1U);
}

TEST_F(RoomStorePauseTest, TheShotClockDoesNotRunWhileTheMatchIsPaused) {
    clock_.advance_ms(static_cast<std::int64_t>(3 * kShotClockS * 1000)); // far past the clock
    paused_room_.tick();
    ASSERT_EQ(b_->events<proto::PausedEvent>().size(), 1U);
    confirm_and_play_out();
    const auto turns = b_->events<proto::TurnEvent>();
    ASSERT_FALSE(turns.empty());
    ASSERT_TRUE(turns.back().deadline_ms);
    // The next turn starts when the stroke has streamed, with the whole shot clock.
    EXPECT_EQ(*turns.back().deadline_ms - turns.back().server_time_ms,
              static_cast<std::int64_t>(kShotClockS * 1000));
    EXPECT_EQ(turns.back().turn, 1);
    EXPECT_EQ(paused_room_.match().turn_number, 1);
}

} // namespace
} // namespace carrom::room
