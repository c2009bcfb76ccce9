#include "carrom/client/hermite.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "client/interpolation_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace carrom::client {
namespace {

using test::body;
using test::kGeometry;
using test::snap;

const RenderedBody* find(const std::vector<RenderedBody>& v, int id) {
    const auto it =
        std::find_if(v.begin(), v.end(), [id](const RenderedBody& b) { return b.id == id; });
    return it == v.end() ? nullptr : &*it;
}

TEST(Hermite, HitsTheEndsAndIsExactForUniformMotion) {
    const Vec2 p0{10.0, 20.0};
    const Vec2 v{100.0, -50.0};
    const double dt = 0.1;
    const Vec2 p1 = p0 + v * dt;
    EXPECT_EQ(hermite(p0, v, p1, v, dt, 0.0), p0);
    const Vec2 end = hermite(p0, v, p1, v, dt, 1.0);
    EXPECT_NEAR(end.x, p1.x, 1e-12);
    EXPECT_NEAR(end.y, p1.y, 1e-12);
    const Vec2 mid = hermite(p0, v, p1, v, dt, 0.3);
    EXPECT_NEAR(mid.x, p0.x + v.x * 0.03, 1e-12);
    EXPECT_NEAR(mid.y, p0.y + v.y * 0.03, 1e-12);
}

TEST(Hermite, IsExactForUniformDeceleration) {
    // p(t) = p0 + v0 t + a t^2 / 2 is a cubic (a quadratic), so Hermite reproduces it.
    const double a = -300.0;
    const double v0 = 200.0;
    const double dt = 0.2;
    auto p = [&](double t) { return Vec2{v0 * t + 0.5 * a * t * t, 0.0}; };
    auto v = [&](double t) { return Vec2{v0 + a * t, 0.0}; };
    for (double s : {0.1, 0.5, 0.77}) {
        EXPECT_NEAR(hermite(p(0), v(0), p(dt), v(dt), dt, s).x, p(s * dt).x, 1e-12);
    }
}

TEST(InterpolationBuffer, DeltaNeedsAKeyframe) {
    InterpolationBuffer buf(kGeometry);
    EXPECT_FALSE(buf.push(snap(1, 0.0, false, {body(1, {100, 100})})));
    EXPECT_TRUE(buf.empty());
    EXPECT_TRUE(buf.push(snap(2, 0.0, true, {body(1, {100, 100})})));
    EXPECT_FALSE(buf.empty());
}

TEST(InterpolationBuffer, StaleAndDuplicateSnapshotsAreIgnored) {
    InterpolationBuffer buf(kGeometry);
    ASSERT_TRUE(buf.push(snap(5, 1.0, true, {body(1, {100, 100})})));
    EXPECT_FALSE(buf.push(snap(5, 1.1, false, {body(1, {200, 100})})));
    EXPECT_FALSE(buf.push(snap(4, 1.2, false, {body(1, {200, 100})})));
    EXPECT_FALSE(buf.push(snap(6, 0.9, false, {body(1, {200, 100})})));
    EXPECT_EQ(buf.newest_seq(), 5u);
    EXPECT_EQ((*buf.newest_state())[0].pos_px, (Vec2{100, 100}));
}

TEST(InterpolationBuffer, DeltasKeepUnlistedBodiesAtRest) {
    InterpolationBuffer buf(kGeometry);
    buf.push(snap(1, 0.0, true, {body(1, {100, 100}), body(2, {200, 200}, {50, 0})}));
    buf.push(snap(2, 0.1, false, {body(2, {205, 200}, {40, 0})}));
    const std::vector<BodyState>& s = *buf.newest_state();
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0].pos_px, (Vec2{100, 100}));
    EXPECT_EQ(s[1].pos_px, (Vec2{205, 200}));
    EXPECT_EQ(s[1].vel_px_s, (Vec2{40, 0}));
}

// Constant velocity is the free motion with k = 0.
InterpolationConfig undamped() {
    InterpolationConfig cfg;
    cfg.damping_per_s = 0.0;
    return cfg;
}

TEST(InterpolationBuffer, InterpolatesBetweenStatesWithVelocities) {
    InterpolationBuffer buf(kGeometry, undamped());
    buf.push(snap(1, 0.0, true, {body(1, {100, 100}, {100, 0})}));
    buf.push(snap(2, 0.1, false, {body(1, {110, 100}, {100, 0})}));
    const auto r = buf.sample(0.05);
    ASSERT_EQ(r.size(), 1u);
    EXPECT_NEAR(r[0].pos_px.x, 105.0, 1e-9);
    EXPECT_DOUBLE_EQ(r[0].scale, 1.0);
    EXPECT_DOUBLE_EQ(r[0].alpha, 1.0);
}

TEST(InterpolationBuffer, BeforeTheOldestAndAfterTheNewest) {
    InterpolationConfig cfg = undamped();
    cfg.max_extrapolation_s = 0.05;
    InterpolationBuffer buf(kGeometry, cfg);
    buf.push(snap(1, 1.0, true, {body(1, {100, 100}, {100, 0})}));
    buf.push(snap(2, 1.1, false, {body(1, {110, 100}, {100, 0})}));
    EXPECT_NEAR(buf.sample(0.5)[0].pos_px.x, 100.0, 1e-9);
    EXPECT_NEAR(buf.sample(1.12)[0].pos_px.x, 112.0, 1e-9);
    EXPECT_NEAR(buf.sample(5.0)[0].pos_px.x, 115.0, 1e-9); // extrapolation is capped
}

TEST(InterpolationBuffer, ALongGapAfterRestHoldsInsteadOfGliding) {
    InterpolationBuffer buf(kGeometry);
    buf.push(snap(1, 0.0, true, {body(1, {100, 100})}));
    // The next shot starts 5 s later with the body elsewhere and moving.
    buf.push(snap(2, 5.0, false, {body(1, {300, 300}, {500, 0})}));
    EXPECT_EQ(buf.sample(4.9)[0].pos_px, (Vec2{100, 100}));
    EXPECT_EQ(buf.sample(5.0)[0].pos_px, (Vec2{300, 300}));
}

TEST(InterpolationBuffer, PocketedPieceFallsIntoItsPocket) {
    InterpolationConfig cfg;
    cfg.pocket_anim_s = 0.15;
    InterpolationBuffer buf(kGeometry, cfg);
    // Heading for the bottom-right pocket at (543, 543).
    buf.push(snap(1, 0.0, true, {body(3, {520, 520}, {300, 300}), body(4, {300, 300})}));
    buf.push(snap(2, 1.0 / 60.0, false, {body(3, {525, 525}, {}, true)}));
    const auto early = buf.sample(0.01);
    const RenderedBody* a = find(early, 3);
    ASSERT_NE(a, nullptr);
    EXPECT_TRUE(a->falling);
    EXPECT_LT(a->scale, 1.0);
    EXPECT_LT(a->alpha, 1.0);
    const auto later = buf.sample(0.12);
    const RenderedBody* b = find(later, 3);
    ASSERT_NE(b, nullptr);
    EXPECT_LT(b->scale, a->scale);
    EXPECT_LT(b->alpha, a->alpha);
    EXPECT_LT(length(b->pos_px - kGeometry.pockets[3]), length(a->pos_px - kGeometry.pockets[3]));
    EXPECT_LT(length(b->pos_px - kGeometry.pockets[3]), 1.0);
    EXPECT_EQ(find(buf.sample(0.2), 3), nullptr); // gone once the animation ends
    EXPECT_NE(find(buf.sample(0.2), 4), nullptr);
}

TEST(InterpolationBuffer, PieceReturnedToTheBoardAppearsAtItsNewPlace) {
    InterpolationBuffer buf(kGeometry);
    buf.push(snap(1, 0.0, true, {body(0, {0, 0}, {}, true)}));
    EXPECT_EQ(find(buf.sample(0.0), 0), nullptr);
    buf.push(snap(2, 0.5, true, {body(0, {300, 300})}));
    EXPECT_EQ(find(buf.sample(0.25), 0), nullptr);
    ASSERT_NE(find(buf.sample(0.5), 0), nullptr);
    EXPECT_EQ(find(buf.sample(0.5), 0)->pos_px, (Vec2{300, 300}));
}

TEST(InterpolationBuffer, KeyframeAtTheSameInstantReplacesTheDelta) {
    InterpolationBuffer buf(kGeometry);
    buf.push(snap(1, 0.0, true, {body(1, {100, 100}, {60, 0})}));
    buf.push(snap(2, 0.1, false, {body(1, {106, 100}, {0, 0})}));
    buf.push(snap(3, 0.1, true, {body(1, {106, 100})}));
    EXPECT_EQ(buf.newest_seq(), 3u);
    EXPECT_NEAR(buf.sample(0.05)[0].pos_px.x, 103.0, 1.0);
}

TEST(InterpolationBuffer, OldStatesAreDropped) {
    InterpolationConfig cfg;
    cfg.history_s = 1.0;
    InterpolationBuffer buf(kGeometry, cfg);
    buf.push(snap(1, 0.0, true, {body(1, {100, 100})}));
    for (std::uint64_t i = 2; i < 200; ++i) {
        buf.push(snap(i, static_cast<double>(i) / 60.0, false,
                      {body(1, {100.0 + static_cast<double>(i), 100})}));
    }
    EXPECT_GE(buf.oldest_time(), buf.newest_time() - 1.0 - 1.0 / 60.0);
}

} // namespace
} // namespace carrom::client
