// TrajectoryCursor against state_at: at every snapshot tick of long shots (breaks that move for
// seconds, with dozens of contacts and pockets) the cursor's state is bit-identical to the
// from-start replay, also at repeated times, at segment instants and after a time earlier than
// the previous one.

#include "common/physics_test_util.hpp"

#include "carrom/scene.hpp"
#include "carrom/trajectory_cursor.hpp"

#include <cstring>

namespace carrom {
namespace {

using test::striker;

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void expect_bit_identical(const std::vector<Body>& cursor, const std::vector<Body>& replay,
                          double t_s) {
    ASSERT_EQ(cursor.size(), replay.size());
    for (std::size_t i = 0; i < cursor.size(); ++i) {
        const Body& a = cursor[i];
        const Body& b = replay[i];
        ASSERT_EQ(a.id, b.id);
        ASSERT_EQ(a.pocketed, b.pocketed) << "body " << a.id << " t = " << t_s;
        ASSERT_TRUE(same_bits(a.pos_px.x, b.pos_px.x) && same_bits(a.pos_px.y, b.pos_px.y) &&
                    same_bits(a.vel_px_s.x, b.vel_px_s.x) && same_bits(a.vel_px_s.y, b.vel_px_s.y))
            << "body " << a.id << " t = " << t_s;
    }
}

SimulateResult long_shot(const PhysicsConfig& config, double x_px, double vx, double vy) {
    std::vector<Body> scene = standard_layout(config);
    scene.push_back(striker(kStrikerId, x_px, 520.0, vx, vy));
    SimOptions options;
    options.record_trajectory = true;
    return simulate_exact(config, scene, options);
}

TEST(TrajectoryCursor, EveryTickOfLongShotsIsBitIdenticalToTheReplayFromTheStart) {
    const PhysicsConfig config;
    int shots = 0;
    for (const auto& [x, vx, vy] :
         {std::tuple{300.0, 0.0, -1500.0}, std::tuple{280.0, 90.0, -2400.0},
          std::tuple{330.0, -300.0, -1900.0}}) {
        const SimulateResult sim = long_shot(config, x, vx, vy);
        const Trajectory& trajectory = sim.result.trajectory;
        ASSERT_GT(sim.result.end_time_s, 1.0);
        ASSERT_GT(trajectory.segments.size(), 40U);
        TrajectoryCursor cursor;
        for (int k = 0;; ++k) {
            const double t = std::min(k / 60.0, sim.result.end_time_s);
            expect_bit_identical(cursor.at(config, trajectory, t), state_at(config, trajectory, t),
                                 t);
            if (t >= sim.result.end_time_s) {
                break;
            }
        }
        ++shots;
    }
    EXPECT_EQ(shots, 3);
}

TEST(TrajectoryCursor, SegmentInstantsRepeatsAndAnEarlierTimeMatchTheReplay) {
    const PhysicsConfig config;
    const SimulateResult sim = long_shot(config, 300.0, 0.0, -1500.0);
    const Trajectory& trajectory = sim.result.trajectory;
    TrajectoryCursor cursor;
    // Negative times clamp to 0, as in state_at.
    expect_bit_identical(cursor.at(config, trajectory, -1.0), state_at(config, trajectory, -1.0),
                         -1.0);
    for (const Segment& seg : trajectory.segments) {
        for (double t : {seg.t_s, seg.t_s}) { // the same time twice
            expect_bit_identical(cursor.at(config, trajectory, t), state_at(config, trajectory, t),
                                 t);
        }
    }
    // An earlier time starts again from the first segment.
    for (double t : {0.25, 0.1, 0.0, 0.5}) {
        expect_bit_identical(cursor.at(config, trajectory, t), state_at(config, trajectory, t), t);
    }
}

} // namespace
} // namespace carrom
