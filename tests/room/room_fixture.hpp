#pragma once
// The room tests' fixture: a Room on a manual clock with two players and a spectator to seat
// (FakePeers), and a scripted bot brain.

#include "carrom/room/room.hpp"

#include "room/fake_peer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <numbers>

namespace carrom::room::testing {

inline constexpr double kUp = -std::numbers::pi / 2.0;

class RoomTest : public ::testing::Test {
protected:
    RoomTest() : RoomTest(config()) {}
    explicit RoomTest(const RoomConfig& c) : room_("ABCDEF", c, clock_, counters_) {}

    // A plain 60 Hz stream (most tests count on its regular spacing); the server's default,
    // 10 Hz plus a delta at every change of motion, is in room_contact_snapshots_test.cpp.
    static RoomConfig config() {
        RoomConfig c;
        c.rule_set = proto::RuleSet::Icf;
        c.rules.shot_clock_s = 0.0;
        c.snapshot_hz = 60.0;
        c.contact_snapshots = false;
        c.grace_s = 60.0;
        return c;
    }

    void seat_both() {
        ASSERT_FALSE(room_.join(a_, proto::Role::Player));
        ASSERT_FALSE(room_.join(b_, proto::Role::Player));
    }

    // Advances the manual clock in snapshot steps until the shot has finished.
    int play_out() {
        int ticks = 0;
        while (room_.phase() == proto::Phase::Moving && ticks < 100000) {
            const auto wake = room_.next_wake_ms();
            EXPECT_TRUE(wake.has_value());
            clock_.set_ms(std::max(clock_.now_ms(), *wake));
            room_.tick();
            ++ticks;
        }
        return ticks;
    }

    proto::Shoot break_shot(int turn) const { return {turn, 300.0, kUp, 25.0}; }

    ManualClock clock_;
    RoomCounters counters_;
    Room room_;
    std::shared_ptr<FakePeer> a_ = std::make_shared<FakePeer>(1, "Asha");
    std::shared_ptr<FakePeer> b_ = std::make_shared<FakePeer>(2, "Bo");
    std::shared_ptr<FakePeer> watcher_ = std::make_shared<FakePeer>(3, "Cy");
};

// A bot brain that always plays the same shot.
class ScriptedBrain final : public BotBrain {
public:
    Shot choose_shot(const rules::MatchState&, int, std::chrono::milliseconds) override {
        return {300.0, 1.2, 5.0};
    }
};

} // namespace carrom::room::testing
