#include "carrom/client/playout_clock.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

namespace carrom::client {
namespace {

TEST(PlayoutClock, SteadySnapshotsGiveTwoIntervalsOfDelay) {
    PlayoutClock clock;
    for (int i = 0; i < 120; ++i) {
        const double t = i / 30.0;
        clock.on_snapshot(t, 100.0 + t + 0.04); // 40 ms one-way, no jitter, 30 Hz
    }
    EXPECT_NEAR(clock.interval_s(), 1.0 / 30.0, 1e-6);
    EXPECT_NEAR(clock.jitter_s(), 0.0, 1e-9);
    EXPECT_NEAR(clock.base_transit_s(), 100.04, 1e-9);
    EXPECT_NEAR(clock.delay_s(), 2.0 / 30.0, 1e-6);
    EXPECT_NEAR(clock.target_time(104.0), 104.0 - 100.04 - 2.0 / 30.0, 1e-6);
}

TEST(PlayoutClock, JitterRaisesTheDelayAndThenDecays) {
    PlayoutConfig cfg;
    cfg.jitter_decay_s = 1.0;
    PlayoutClock clock(cfg);
    for (int i = 0; i < 60; ++i) {
        clock.on_snapshot(i / 60.0, i / 60.0);
    }
    const double calm = clock.delay_s();
    clock.on_snapshot(1.0, 1.0 + 0.03); // one snapshot 30 ms late
    EXPECT_NEAR(clock.jitter_s(), 0.03, 1e-9);
    EXPECT_NEAR(clock.delay_s(), calm + 0.03, 1e-6);
    for (int i = 61; i < 400; ++i) {
        clock.on_snapshot(i / 60.0, i / 60.0);
    }
    EXPECT_LT(clock.jitter_s(), 0.03 * 0.01);
}

TEST(PlayoutClock, DelayIsClamped) {
    PlayoutConfig cfg;
    cfg.max_delay_s = 0.1;
    PlayoutClock clock(cfg);
    clock.on_snapshot(0.0, 0.0);
    clock.on_snapshot(0.01, 2.0); // two seconds late
    EXPECT_DOUBLE_EQ(clock.delay_s(), 0.1);
}

TEST(PlayoutClock, RenderTimeAdvancesSmoothlyAndNeverBackwards) {
    PlayoutClock clock;
    std::mt19937 rng(7);
    double last = -1e9;
    double local = 0.0;
    double max_step = 0.0;
    int next = 0;
    for (int frame = 0; frame < 600; ++frame) {
        local = frame / 60.0;
        // 60 Hz snapshots with up to 20 ms of extra delay each.
        while (next / 60.0 + 0.02 <= local) {
            const double jitter = 0.02 * static_cast<double>(rng()) / 4294967295.0;
            clock.on_snapshot(next / 60.0, next / 60.0 + 0.05 + jitter);
            ++next;
        }
        if (!clock.has_data()) {
            continue;
        }
        const double r = clock.render_time(local);
        if (last > -1e9) {
            EXPECT_GE(r, last);
            max_step = std::max(max_step, r - last);
        }
        last = r;
    }
    // Each frame advances about one frame's time (slewing adds at most 10 %).
    EXPECT_LE(max_step, 1.1 / 60.0 + 1e-9);
}

TEST(PlayoutClock, LargeErrorsSnapAtOnce) {
    PlayoutClock clock;
    clock.on_snapshot(0.0, 0.0);
    const double r0 = clock.render_time(0.0);
    // The server's clock jumps 10 s ahead (a new match).
    for (int i = 0; i < 200; ++i) {
        clock.on_snapshot(10.0 + i / 60.0, 0.01 + i / 60.0);
    }
    const double r1 = clock.render_time(0.02);
    EXPECT_GT(r1 - r0, 9.0);
}

} // namespace
} // namespace carrom::client
