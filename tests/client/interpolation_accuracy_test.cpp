// Rendering error of the interpolation path (playout clock + buffer) against the exact
// trajectory of the standard break, at several snapshot rates with 10 ms of arrival jitter.
// The numbers are reported in docs/client.md.

#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/playout_clock.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/proto/codec.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"

#include <gtest/gtest.h>

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
    long missing = 0; // bodies on the board in truth but not drawn
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
// first and last; each arrives after a 50 ms path plus uniform jitter in [0, jitter_s].
std::vector<Arrival> stream(const PhysicsConfig& config, const SimResult& sim, double rate_hz,
                            double jitter_s, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<Arrival> out;
    std::vector<Body> last;
    const int frames = static_cast<int>(std::ceil(sim.end_time_s * rate_hz));
    for (int k = 0; k <= frames; ++k) {
        const double t = std::min(k / rate_hz, sim.end_time_s);
        const std::vector<Body> now = state_at(config, sim.trajectory, t);
        Snapshot s;
        s.seq = static_cast<std::uint64_t>(k + 1);
        s.time_s = t;
        s.keyframe = k == 0 || k == frames;
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
        const double jitter = jitter_s * static_cast<double>(rng()) / 4294967295.0;
        out.push_back({t + 0.05 + jitter, std::move(s)});
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const Arrival& a, const Arrival& b) { return a.local_s < b.local_s; });
    return out;
}

ErrorStats measure(const PhysicsConfig& config, const SimResult& sim, double rate_hz,
                   double jitter_s) {
    const std::vector<Arrival> arrivals = stream(config, sim, rate_hz, jitter_s, 12345);
    InterpolationBuffer buffer(make_board_geometry(config));
    PlayoutClock clock;
    std::size_t next = 0;
    double sum2 = 0.0;
    ErrorStats stats;
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
    static ErrorStats run(double rate_hz) {
        const ErrorStats s = measure(config_, *sim_, rate_hz, 0.010);
        std::cout << "[ interp ] break, " << rate_hz << " Hz snapshots, 10 ms jitter: RMS "
                  << s.rms_px << " px, max " << s.max_px << " px over " << s.samples
                  << " moving-body samples, " << s.missing << " missing\n";
        return s;
    }
    static inline PhysicsConfig config_{};
    static inline SimResult* sim_ = nullptr;
};

TEST_F(InterpolationAccuracy, SixtyHertzIsUnderHalfAPixelRms) {
    ASSERT_GT(sim_->end_time_s, 1.0);
    const ErrorStats s = run(60.0);
    EXPECT_GT(s.samples, 1000);
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 0.5);
}

TEST_F(InterpolationAccuracy, ThirtyHertz) {
    const ErrorStats s = run(30.0);
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 1.5);
}

TEST_F(InterpolationAccuracy, TwentyHertz) {
    const ErrorStats s = run(20.0);
    EXPECT_EQ(s.missing, 0);
    EXPECT_LT(s.rms_px, 3.0);
}

TEST_F(InterpolationAccuracy, ErrorGrowsAsSnapshotsThinOut) {
    EXPECT_LT(measure(config_, *sim_, 60.0, 0.010).rms_px,
              measure(config_, *sim_, 20.0, 0.010).rms_px);
}

} // namespace
} // namespace carrom::client
