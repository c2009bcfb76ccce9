// The server's default stream: a delta at the instant of every change of motion (a contact, a
// stop, a pocketing) plus 10 Hz in between, so that a client continuing the newest state along
// the damped free motion draws the shot exactly (docs/protocol.md, "Snapshots").
#include "room/room_fixture.hpp"

#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"
#include "carrom/trajectory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace carrom::room {
namespace {

using testing::RoomTest;

class ContactSnapshotTest : public RoomTest {
protected:
    ContactSnapshotTest() : RoomTest(contact_config()) {}

    static RoomConfig contact_config() {
        RoomConfig c = config();
        c.snapshot_hz = 10.0;
        c.contact_snapshots = true;
        return c;
    }

    // The break as the room plays it: the same rules call on the same board.
    SimResult expected_break() {
        rules::PlayOptions options;
        options.record_trajectory = true;
        ExactEngine engine(contact_config().physics);
        const RoomConfig c = contact_config();
        const rules::MatchState before = rules::new_match(rules::RuleSet::Icf, c.rules, c.physics);
        rules::PlayResult r =
            rules::play_shot(before, 0, Shot{300.0, testing::kUp, 25.0}, engine, options);
        EXPECT_FALSE(r.error.has_value());
        return r.outcome.physics;
    }

    void break_and_play_out() {
        seat_both();
        a_->clear();
        room_.shoot(*a_, break_shot(0));
        ASSERT_TRUE(a_->error_codes().empty());
        play_out();
    }
};

TEST_F(ContactSnapshotTest, EveryChangeOfMotionHasADeltaAtItsInstant) {
    break_and_play_out();
    const SimResult sim = expected_break();
    const auto snaps = a_->all<proto::Snapshot>();
    std::set<double> sent;
    for (const auto& s : snaps) {
        sent.insert(s.t_s);
    }
    ASSERT_FALSE(sim.trajectory.segments.empty());
    for (const Segment& seg : sim.trajectory.segments) {
        if (seg.t_s > 0.0) {
            EXPECT_TRUE(sent.count(seg.t_s)) << "no delta at the change at t " << seg.t_s;
        }
    }
}

TEST_F(ContactSnapshotTest, DeltasAreTheExactStateRoundedAndInTimeOrder) {
    break_and_play_out();
    const SimResult sim = expected_break();
    const auto snaps = a_->all<proto::Snapshot>();
    ASSERT_GT(snaps.size(), 10U);
    for (std::size_t i = 1; i < snaps.size(); ++i) {
        EXPECT_EQ(snaps[i].seq, snaps[i - 1].seq + 1);
        EXPECT_GT(snaps[i].t_s, snaps[i - 1].t_s - 1e-12);
    }
    for (const auto& s : snaps) {
        if (s.keyframe) {
            continue;
        }
        const std::vector<Body> truth = state_at(contact_config().physics, sim.trajectory, s.t_s);
        for (const proto::SnapshotBody& b : s.bodies) {
            const auto it = std::find_if(truth.begin(), truth.end(),
                                         [&](const Body& t) { return t.id == b.id; });
            ASSERT_NE(it, truth.end());
            EXPECT_LE(std::abs(it->pos_px.x - b.pos_px.x), 0.005 + 1e-9);
            EXPECT_LE(std::abs(it->pos_px.y - b.pos_px.y), 0.005 + 1e-9);
        }
    }
}

TEST_F(ContactSnapshotTest, RegularDeltasAtTenHertzInBetweenAndUnderHalfOfSixtyHertz) {
    break_and_play_out();
    const auto snaps = a_->all<proto::Snapshot>();
    const double duration = snaps.back().t_s;
    ASSERT_GT(duration, 1.0);
    for (std::size_t i = 1; i < snaps.size(); ++i) {
        EXPECT_LE(snaps[i].t_s - snaps[i - 1].t_s, 0.1 + 0.002) << "at t " << snaps[i].t_s;
    }
    EXPECT_LT(2.0 * static_cast<double>(snaps.size()), duration * 60.0);
}

TEST_F(ContactSnapshotTest, RoomStateSaysHowThePiecesMove) {
    seat_both();
    const proto::RoomState state = room_.room_state(0);
    EXPECT_TRUE(state.motion.contact_snapshots);
    EXPECT_EQ(state.motion.damping_per_s, PhysicsConfig{}.damping_per_s);
}

} // namespace
} // namespace carrom::room
