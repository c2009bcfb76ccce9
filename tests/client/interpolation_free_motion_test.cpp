// The buffer draws the damped free motion p(t) = p0 + v0 (1 - e^(-k dt)) / k between states it
// explains: none or one change of motion between them (docs/interpolation.md, "Sampling a
// time"). States here are built from that formula, with k the physics default.

#include "carrom/client/hermite.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/trajectory.hpp"
#include "client/interpolation_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace carrom::client {
namespace {

using test::body;
using test::kGeometry;
using test::snap;

const PhysicsConfig kPhysics{};
const double kK = kPhysics.damping_per_s;

Vec2 at(Vec2 p, Vec2 v, double dt) {
    return p + v * travel_factor_s(kK, dt);
}

Vec2 speed_after(Vec2 v, double dt) {
    return v * std::exp(-kK * dt);
}

Vec2 drawn(const InterpolationBuffer& buf, double t, int id = 1) {
    const std::vector<RenderedBody> r = buf.sample(t);
    const auto it =
        std::find_if(r.begin(), r.end(), [id](const RenderedBody& b) { return b.id == id; });
    EXPECT_NE(it, r.end()) << "body " << id << " not drawn at " << t;
    return it == r.end() ? Vec2{} : it->pos_px;
}

TEST(InterpolationFreeMotion, NoChangeBetweenTwoStatesIsTheFormula) {
    InterpolationBuffer buf(kGeometry);
    const Vec2 p{100, 100}, v{800, -300};
    buf.push(snap(1, 0.0, true, {body(1, p, v)}));
    buf.push(snap(2, 0.1, false, {body(1, at(p, v, 0.1), speed_after(v, 0.1))}));
    for (const double t : {0.0, 0.013, 0.05, 0.0999}) {
        EXPECT_LT(length(drawn(buf, t) - at(p, v, t)), 1e-9) << t;
    }
}

// A body that bounces off something at 0.063 s, between two regular states.
TEST(InterpolationFreeMotion, OneChangeIsDrawnExactlyOnBothSidesOfItsInstant) {
    InterpolationBuffer buf(kGeometry);
    const Vec2 p{100, 300}, v{900, 200};
    const double c = 0.063;
    const Vec2 pc = at(p, v, c);
    const Vec2 vc{-0.7 * speed_after(v, c).x, speed_after(v, c).y}; // off a cushion
    buf.push(snap(1, 0.0, true, {body(1, p, v)}));
    buf.push(snap(2, 0.1, false, {body(1, at(pc, vc, 0.1 - c), speed_after(vc, 0.1 - c))}));
    for (const double t : {0.01, 0.04, 0.0629}) {
        EXPECT_LT(length(drawn(buf, t) - at(p, v, t)), 1e-6) << t;
    }
    for (const double t : {0.0631, 0.08, 0.0999}) {
        EXPECT_LT(length(drawn(buf, t) - at(pc, vc, t - c)), 1e-6) << t;
    }
    // Hermite would cut the corner by more than a pixel.
    const Vec2 curve = hermite(p, v, at(pc, vc, 0.1 - c), speed_after(vc, 0.1 - c), 0.1, 0.63);
    EXPECT_GT(length(curve - pc), 1.0);
}

TEST(InterpolationFreeMotion, TwoChangesFallBackToHermite) {
    InterpolationBuffer buf(kGeometry);
    const Vec2 p{100, 300}, v{900, 0};
    const Vec2 p1 = at(p, v, 0.03);
    const Vec2 v1{0, 700};
    const Vec2 p2 = at(p1, v1, 0.04);
    const Vec2 v2{-600, 0};
    const Vec2 pb = at(p2, v2, 0.03);
    const Vec2 vb = speed_after(v2, 0.03);
    buf.push(snap(1, 0.0, true, {body(1, p, v)}));
    buf.push(snap(2, 0.1, false, {body(1, pb, vb)}));
    EXPECT_LT(length(drawn(buf, 0.05) - hermite(p, v, pb, vb, 0.1, 0.5)), 1e-9);
}

TEST(InterpolationFreeMotion, AChangeAtTheNewerStatesInstantIsNoChangeBefore) {
    InterpolationBuffer buf(kGeometry);
    const Vec2 p{200, 200}, v{0, 500};
    // The server's change delta: at its instant, with the velocity after the contact.
    buf.push(snap(1, 0.0, true, {body(1, p, v)}));
    buf.push(snap(2, 0.07, false, {body(1, at(p, v, 0.07), {300, -200})}));
    EXPECT_LT(length(drawn(buf, 0.069) - at(p, v, 0.069)), 1e-9);
}

TEST(InterpolationFreeMotion, PastTheNewestStateAQuarterSecondWhenEveryChangeIsSent) {
    const Vec2 p{100, 100}, v{400, 0};
    InterpolationBuffer regular(kGeometry);
    InterpolationBuffer every_change(kGeometry);
    every_change.set_motion(kK, true);
    for (InterpolationBuffer* buf : {&regular, &every_change}) {
        buf->push(snap(1, 1.0, true, {body(1, p, v)}));
    }
    EXPECT_LT(length(drawn(regular, 1.03) - at(p, v, 0.03)), 1e-9);
    EXPECT_LT(length(drawn(regular, 2.0) - at(p, v, 0.05)), 1e-9);
    EXPECT_LT(length(drawn(every_change, 1.2) - at(p, v, 0.2)), 1e-9);
    EXPECT_LT(length(drawn(every_change, 2.0) - at(p, v, 0.25)), 1e-9);
}

TEST(InterpolationFreeMotion, APieceMovesOnUntilItsPocketingInstantThenFalls) {
    InterpolationBuffer buf(kGeometry);
    buf.set_motion(kK, true);
    const Vec2 p{480, 480}, v{300, 300};
    buf.push(snap(1, 0.0, true, {body(1, p, v)}));
    buf.push(snap(2, 0.08, false, {body(1, at(p, v, 0.08), {}, true)}));
    for (const double t : {0.01, 0.04, 0.079}) {
        EXPECT_LT(length(drawn(buf, t) - at(p, v, t)), 1e-9) << t;
    }
    const std::vector<RenderedBody> after = buf.sample(0.1);
    ASSERT_EQ(after.size(), 1u);
    EXPECT_TRUE(after[0].falling);
}

TEST(InterpolationFreeMotion, DampingFromTheServerIsUsed) {
    InterpolationBuffer buf(kGeometry);
    const double k = 2.0;
    buf.set_motion(k, false);
    const Vec2 p{100, 100}, v{500, 0};
    const Vec2 pb = p + v * travel_factor_s(k, 0.1);
    buf.push(snap(1, 0.0, true, {body(1, p, v)}));
    buf.push(snap(2, 0.1, false, {body(1, pb, v * std::exp(-k * 0.1))}));
    EXPECT_LT(length(drawn(buf, 0.05) - (p + v * travel_factor_s(k, 0.05))), 1e-9);
}

} // namespace
} // namespace carrom::client
