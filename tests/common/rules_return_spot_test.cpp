// Returned pieces: the free spot nearest the centre, never overlapping, deterministic.

#include "rules_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace carrom::rules {
namespace {

const PhysicsConfig kPhysics{};

bool fits(const std::vector<Body>& bodies, Vec2 p, double r) {
    if (p.x < kPhysics.cushion_min(r) || p.x > kPhysics.cushion_max(r) ||
        p.y < kPhysics.cushion_min(r) || p.y > kPhysics.cushion_max(r)) {
        return false;
    }
    for (const Body& b : bodies) {
        if (!b.pocketed && length(b.pos_px - p) < r + kPhysics.radius(b.kind)) {
            return false;
        }
    }
    return true;
}

// Brute force: the nearest free point of a 0.25 px grid around the centre.
double grid_nearest(const std::vector<Body>& bodies, double r) {
    const Vec2 c = kPhysics.centre();
    double best = 1e9;
    for (double y = 100.0; y <= 500.0; y += 0.25) {
        for (double x = 100.0; x <= 500.0; x += 0.25) {
            const double d = length(Vec2{x, y} - c);
            if (d < best && fits(bodies, {x, y}, r)) {
                best = d;
            }
        }
    }
    return best;
}

TEST(RulesReturnSpot, FreeCentreIsTheSpot) {
    std::vector<Body> bodies = standard_layout(kPhysics);
    bodies[0].pocketed = true;
    EXPECT_EQ(free_spot_near_centre(kPhysics, bodies, 14.0), (Vec2{300.0, 300.0}));
}

TEST(RulesReturnSpot, OccupiedCentreGivesTheNearestFreeSpotWithoutOverlap) {
    std::vector<Body> bodies = standard_layout(kPhysics); // the queen sits on the centre
    const Vec2 spot = free_spot_near_centre(kPhysics, bodies, 14.0);
    EXPECT_TRUE(fits(bodies, spot, 14.0));
    const double d = length(spot - kPhysics.centre());
    EXPECT_LE(d, grid_nearest(bodies, 14.0) + 1e-5);
    EXPECT_GT(d, 28.0); // it cannot sit closer than touching the queen
}

TEST(RulesReturnSpot, OneBodyOnTheCentrePushesStraightUp) {
    std::vector<Body> bodies{Body{0, BodyKind::Queen, {300.0, 300.0}, {}, false}};
    const Vec2 spot = free_spot_near_centre(kPhysics, bodies, 14.0);
    EXPECT_NEAR(spot.x, 300.0, 1e-12);
    EXPECT_NEAR(spot.y, 300.0 - 28.0, 1e-5);
    EXPECT_TRUE(fits(bodies, spot, 14.0));
}

TEST(RulesReturnSpot, RandomCrowdsNeverOverlapAndFindTheNearestSpot) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> coord(200.0, 400.0);
    for (int scene = 0; scene < 20; ++scene) {
        std::vector<Body> bodies;
        for (int id = 0; id < 19 * 40 && bodies.size() < 19; ++id) {
            const Vec2 p{coord(rng), coord(rng)};
            if (fits(bodies, p, 14.0)) {
                bodies.push_back(
                    Body{static_cast<int>(bodies.size()), BodyKind::Black, p, {}, false});
            }
        }
        const Vec2 spot = free_spot_near_centre(kPhysics, bodies, 14.0);
        ASSERT_TRUE(fits(bodies, spot, 14.0)) << scene;
        EXPECT_LE(length(spot - kPhysics.centre()), grid_nearest(bodies, 14.0) + 1e-5) << scene;
        EXPECT_EQ(free_spot_near_centre(kPhysics, bodies, 14.0), spot); // deterministic
    }
}

TEST(RulesReturnSpot, SeveralReturnsInOneStrokeNeverOverlap) {
    MatchState m = test::broken(RuleSet::Icf);
    for (int id : {2, 4, 6, 8}) {
        test::pre_pocket(m, id, 0);
    }
    const StrokeResult r = test::stroke(m, {10, 12, 14}, true); // 3 back + 1 due
    EXPECT_EQ(r.outcome.returned.size(), 4u);
    EXPECT_FALSE(test::overlaps_any(r.state));
    EXPECT_FALSE(validate_scene(r.state.physics, r.state.bodies).has_value());
}

// The queen goes back to the centre (../shared/reference/carrom-rules.md), even when own coins
// come back in the same stroke: they are placed around it.
TEST(RulesReturnSpot, QueenReturnedWithOwnCoinsTakesTheCentre) {
    MatchState m = test::broken(RuleSet::Icf);
    test::pre_pocket(m, 2, 0);                               // an own coin in: the queen may fall
    const StrokeResult r = test::stroke(m, {4, 0, 6}, true); // striker foul: 4, 6 and queen back
    const Vec2 centre = r.state.physics.centre();
    ASSERT_EQ(r.outcome.returned.size(), 4u); // 4, 6, the queen, and one due (coin 2)
    bool queen_seen = false;
    for (const ReturnedPiece& back : r.outcome.returned) {
        const Body& body = r.state.bodies[static_cast<std::size_t>(back.id)];
        EXPECT_FALSE(body.pocketed) << back.id;
        EXPECT_EQ(body.pos_px, back.pos_px) << back.id;
        if (back.id == kQueenId) {
            queen_seen = true;
            EXPECT_EQ(back.pos_px, centre);
        } else {
            EXPECT_GT(length(back.pos_px - centre), 2.0 * r.state.physics.coin_radius_px - 1e-9)
                << back.id;
        }
    }
    EXPECT_TRUE(queen_seen);
    EXPECT_FALSE(test::overlaps_any(r.state));
    EXPECT_FALSE(validate_scene(r.state.physics, r.state.bodies).has_value());
}

// Without the queen, several returned pieces are placed in the order they were returned.
TEST(RulesReturnSpot, FirstReturnedCoinTakesAFreeCentre) {
    MatchState m = test::broken(RuleSet::Icf);
    test::pre_pocket(m, 0, 0); // the queen is off the board before the stroke (pending elsewhere)
    m.queen = QueenState{QueenStatus::Covered, 0};
    const StrokeResult r = test::stroke(m, {4, 6}, true);
    ASSERT_GE(r.outcome.returned.size(), 2u);
    EXPECT_EQ(r.outcome.returned[0].id, 4);
    EXPECT_EQ(r.outcome.returned[0].pos_px, r.state.physics.centre());
    EXPECT_FALSE(test::overlaps_any(r.state));
}

} // namespace
} // namespace carrom::rules
