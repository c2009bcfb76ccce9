// Rendering error of the interpolation path (playout clock + buffer) against the exact
// trajectory of the standard break, at several snapshot rates with 10 ms of arrival jitter, with
// and without a snapshot at every change of motion (the server's default: 10 Hz plus those).
// The numbers are reported in docs/interpolation.md.

#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/playout_clock.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/proto/codec.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numbers>
#include <random>

namespace carrom::client {
namespace {

struct Arrival {
    double local_s;
    Snapshot snapshot;
};

struct ErrorStats {
    double rms_px = 0.0;
    double max_px = 0.0;
    long samples = 0;
    long missing = 0;   // bodies on the board in truth but not drawn
    long snapshots = 0; // messages the stream took
};

// How the server streams the shot: regular snapshots at rate_hz, and with contacts one more at
// the instant of every change of motion (as room::Room does with contact_snapshots).
struct Cadence {
    double rate_hz = 60.0;
    bool contacts = false;
};

SimResult break_shot(const PhysicsConfig& config) {
    std::vector<Body> bodies = standard_layout(config);
    bodies.push_back(make_striker(config, Baseline::Bottom,
                                  Shot{300.0, -std::numbers::pi / 2.0, config.max_power}));
    SimOptions options;
    options.record_trajectory = true;
    SimulateResult r = simulate_exact(config, bodies, options);
    EXPECT_FALSE(r.error.has_value());
    return r.result;
}

// Snapshots as the server sends them: quantised to 1/100, deltas of moved bodies, a keyframe
// first and last; each arrives after a 50 ms path plus uniform jitter in [0, jitter_s], in order.
std::vector<Arrival> stream(const PhysicsConfig& config, const SimResult& sim, Cadence cadence,
                            double jitter_s, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<Arrival> out;
    std::vector<Body> last;
    std::vector<double> times;
    const int frames = static_cast<int>(std::ceil(sim.end_time_s * cadence.rate_hz));
    for (int k = 0; k <= frames; ++k) {
        times.push_back(std::min(k / cadence.rate_hz, sim.end_time_s));
    }
    if (cadence.contacts) {
        for (const Segment& seg : sim.trajectory.segments) {
            times.push_back(seg.t_s);
        }
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    for (std::size_t k = 0; k < times.size(); ++k) {
        const double t = times[k];
        const std::vector<Body> now = state_at(config, sim.trajectory, t);
        Snapshot s;
        s.seq = static_cast<std::uint64_t>(k + 1);
        s.time_s = t;
        s.keyframe = k == 0 || k + 1 == times.size();
        for (std::size_t i = 0; i < now.size(); ++i) {
            const Body& b = now[i];
            const bool changed = last.empty() || b.pocketed != last[i].pocketed ||
                                 b.pos_px != last[i].pos_px || b.vel_px_s != last[i].vel_px_s;
            if (s.keyframe || changed) {
                s.bodies.push_back({b.id,
                                    b.kind,
                                    {proto::quantise(b.pos_px.x), proto::quantise(b.pos_px.y)},
                                    {proto::quantise(b.vel_px_s.x), proto::quantise(b.vel_px_s.y)},
                                    b.pocketed});
            }
        }
        last = now;
        // In order, as TCP delivers: a snapshot waits for the one before it.
        const double jitter = jitter_s * static_cast<double>(rng()) / 4294967295.0;
        const double arrival = std::max(t + 0.05 + jitter, out.empty() ? 0.0 : out.back().local_s);
        out.push_back({arrival, std::move(s)});
    }
    return out;
}

ErrorStats measure(const PhysicsConfig& config, const SimResult& sim, Cadence cadence,
                   double jitter_s) {
    const std::vector<Arrival> arrivals = stream(config, sim, cadence, jitter_s, 12345);
    InterpolationBuffer buffer(make_board_geometry(config));
    PlayoutClock clock;
    if (cadence.contacts) { // as MatchModel does for a room_state with motion.contact_snapshots
        buffer.set_motion(config.damping_per_s, true);
        clock.set_interval_factor(0.0);
    }
    std::size_t next = 0;
    double sum2 = 0.0;
    ErrorStats stats;
    stats.snapshots = static_cast<long>(arrivals.size());
    const double start = arrivals.front().local_s;
    for (double local = start; local < start + sim.end_time_s + 0.5; local += 1.0 / 60.0) {
        for (; next < arrivals.size() && arrivals[next].local_s <= local; ++next) {
            if (buffer.push(arrivals[next].snapshot)) {
                clock.on_snapshot(arrivals[next].snapshot.time_s, arrivals[next].local_s);
            }
        }
        const double t = clock.render_time(local);
        if (t < 0.0 || t > sim.end_time_s) {
            continue;
        }
        const std::vector<RenderedBody> drawn = buffer.sample(t);
        for (const Body& truth : state_at(config, sim.trajectory, t)) {
            if (truth.pocketed || (truth.vel_px_s.x == 0.0 && truth.vel_px_s.y == 0.0)) {
                continue; // only moving bodies count
            }
            const auto it = std::find_if(drawn.begin(), drawn.end(),
                                         [&](const RenderedBody& b) { return b.id == truth.id; });
            if (it == drawn.end()) {
                ++stats.missing;
                continue;
            }
            if (it->falling) {
                continue; // already animating into the pocket it is about to enter
            }
            const double e = length(it->pos_px - truth.pos_px);
            sum2 += e * e;
            stats.max_px = std::max(stats.max_px, e);
            ++stats.samples;
        }
    }
    stats.rms_px = stats.samples > 0 ? std::sqrt(sum2 / static_cast<double>(stats.samples)) : 0.0;
    return stats;
}

class InterpolationAccuracy : public ::testing::Test {
protected:
    static void SetUpTestSuite() { sim_ = new SimResult(break_shot(config_)); }
    static void TearDownTestSuite() {
        delete sim_;
        sim_ = nullptr;
    }
    static ErrorStats run(Cadence cadence) {
        const ErrorStats s = measure(config_, *sim_, cadence, 0.010);
        std::cout << "[ interp ] break, " << cadence.rate_hz << " Hz snapshots"
                  << (cadence.contacts ? " + one per change of motion" : "")
                  << ", 10 ms jitter: RMS " << s.rms_px << " px, max " << s.max_px << " px over "
                  << s.samples << " moving-body samples, " << s.missing << " missing, "
                  << s.snapshots << " snapshots\n";
        return s;
    }
    static inline PhysicsConfig config_{};
    static inline SimResult* sim_ = nullptr;
};

TEST_F(InterpolationAccuracy, SixtyHertzIsUnderHalfAPixelRms) {
    ASSERT_GT(sim_->end_time_s, 1.0);
    const ErrorStats s = run({60.0, false});
    EXPECT_GT(s.samples, 1000);
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 0.5);
}

TEST_F(InterpolationAccuracy, ThirtyHertz) {
    const ErrorStats s = run({30.0, false});
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 1.5);
}

TEST_F(InterpolationAccuracy, TwentyHertz) {
    const ErrorStats s = run({20.0, false});
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 3.0);
}

TEST_F(InterpolationAccuracy, ErrorGrowsAsSnapshotsThinOut) {
    EXPECT_LT(measure(config_, *sim_, {60.0, false}, 0.010).rms_px,
              measure(config_, *sim_, {20.0, false}, 0.010).rms_px);
}

// The server's default: the free motion between changes of motion is drawn exactly, so the
// error is the snapshots' rounding, with under half of the messages of 60 Hz.
TEST_F(InterpolationAccuracy, TenHertzPlusEveryChangeOfMotionIsExactWithUnderHalfTheMessages) {
    const ErrorStats s = run({10.0, true});
    const ErrorStats sixty = measure(config_, *sim_, {60.0, false}, 0.010);
    EXPECT_GT(s.samples, 1000);
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 0.01); // the positions' rounding is 0.005 px
    EXPECT_LT(s.max_px, 0.02);
    EXPECT_LT(2 * s.snapshots, sixty.snapshots);
}

TEST_F(InterpolationAccuracy, EveryChangeOfMotionAtTwentyThirtyAndSixtyHertz) {
    for (const double hz : {20.0, 30.0, 60.0}) {
        const ErrorStats s = run({hz, true});
        EXPECT_EQ(s.missing, 0);
        EXPECT_LT(s.rms_px, 0.01);
        EXPECT_LT(s.max_px, 0.02);
    }
}

// Without the change instants the free motion still draws exactly every interval with at most
// one change of motion per body; Hermite takes the rest.
TEST_F(InterpolationAccuracy, TenHertzWithoutChangesOfMotion) {
    const ErrorStats s = run({10.0, false});
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 5.0);
}

} // namespace
} // namespace carrom::client
