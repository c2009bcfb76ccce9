// first_contact: the striker's first piece, where it touches and where the piece goes, from the
// exact engine; exact small scenes checked against the closed forms of docs/physics.md.
#include "carrom/first_contact.hpp"

#include "physics_test_util.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace carrom {
namespace {

using test::coin;
using test::striker;

constexpr double kTolPx = 1e-9;

// Speed after travelling s px from speed v0 under linear damping: dv/ds = -k.
double speed_after(const PhysicsConfig& config, double v0, double s) {
    return v0 - config.damping_per_s * s;
}

// The coin's speed after a head-on hit by the striker arriving at u (striker mass 2, coin 1).
double head_on_coin_speed(const PhysicsConfig& config, double u) {
    const double m1 = config.striker_mass;
    const double m2 = config.coin_mass;
    return (1.0 + config.disc_restitution) * m1 / (m1 + m2) * u;
}

std::optional<FirstContact> contact_of(const std::vector<Body>& bodies) {
    const PhysicsConfig config;
    ExactEngine engine(config);
    return first_contact(engine, bodies);
}

TEST(FirstContact, HeadOnHitsTheCoinOnTheLine) {
    const auto c = contact_of({coin(1, 300, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 1);
}

TEST(FirstContact, HeadOnStrikerTouchesAtTheSumOfRadii) {
    const auto c = contact_of({coin(1, 300, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_NEAR(c->striker_px.x, 300.0 - 32.0, kTolPx);
    EXPECT_EQ(c->striker_px.y, 300.0);
    EXPECT_EQ(c->piece_px, (Vec2{300.0, 300.0}));
}

TEST(FirstContact, HeadOnPieceGoesStraightOn) {
    const auto c = contact_of({coin(1, 300, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_direction, (Vec2{1.0, 0.0}));
}

TEST(FirstContact, HeadOnPieceSpeedIsTheTwoDiscImpulse) {
    const PhysicsConfig config;
    const auto c = contact_of({coin(1, 300, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    const double u = speed_after(config, 600.0, 118.0);
    EXPECT_NEAR(c->piece_vel_px_s.x, head_on_coin_speed(config, u), 1e-6);
    EXPECT_EQ(c->piece_vel_px_s.y, 0.0);
}

TEST(FirstContact, ContactTimeMatchesTheDampedTravel) {
    const PhysicsConfig config;
    const auto c = contact_of({coin(1, 300, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    // s(t) = v0 (1 - e^(-k t)) / k = 118  =>  t = -ln(1 - 118 k / v0) / k
    const double k = config.damping_per_s;
    EXPECT_NEAR(c->t_s, -std::log(1.0 - 118.0 * k / 600.0) / k, 1e-12);
}

TEST(FirstContact, CutShotSendsThePieceAlongTheLineOfCentres) {
    // Offset 16 px = half the sum of radii: the line of centres is 30 degrees off the path.
    const auto c = contact_of({coin(1, 300, 316), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 1);
    EXPECT_NEAR(c->striker_px.x, 300.0 - std::sqrt(32.0 * 32.0 - 16.0 * 16.0), kTolPx);
    EXPECT_NEAR(c->striker_px.y, 300.0, kTolPx);
    EXPECT_NEAR(c->piece_direction.x, std::sqrt(3.0) / 2.0, 1e-9);
    EXPECT_NEAR(c->piece_direction.y, 0.5, 1e-9);
}

TEST(FirstContact, TheNearerOfTwoCoinsInLineIsTouched) {
    const auto c = contact_of({coin(1, 400, 300), coin(2, 300, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 2);
}

TEST(FirstContact, ACoinBesideThePathIsNotTouched) {
    // 33 px off the path: one more than the sum of radii.
    const auto c = contact_of({coin(1, 300, 333), coin(2, 500, 300), striker(0, 150, 300, 600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 2);
}

TEST(FirstContact, AStrikerThatStopsShortTouchesNothing) {
    // At 60 px/s it travels under 60 / k = 66 px, the coin is 118 px away.
    EXPECT_FALSE(contact_of({coin(1, 300, 300), striker(0, 150, 300, 60, 0)}).has_value());
}

TEST(FirstContact, AStrikerMovingAwayFromEveryPieceTouchesNothing) {
    EXPECT_FALSE(contact_of({coin(1, 300, 300), striker(0, 150, 300, 0, -600)}).has_value());
}

TEST(FirstContact, ACushionBeforeThePieceIsFollowed) {
    // Left into the cushion (centre limit 53 px), back to the right into the coin.
    const auto c = contact_of({coin(1, 300, 300), striker(0, 150, 300, -600, 0)});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 1);
    EXPECT_NEAR(c->striker_px.x, 268.0, kTolPx);
    EXPECT_EQ(c->piece_direction, (Vec2{1.0, 0.0}));
}

TEST(FirstContact, AStrikerAtRestTouchesNothing) {
    EXPECT_FALSE(contact_of({coin(1, 300, 300), striker(0, 150, 300)}).has_value());
}

TEST(FirstContact, ASceneWithoutAStrikerTouchesNothing) {
    EXPECT_FALSE(contact_of({coin(1, 300, 300), coin(2, 150, 300, 600, 0)}).has_value());
}

TEST(FirstContact, AnOverlappingSceneIsRefused) {
    EXPECT_FALSE(contact_of({coin(1, 300, 300), coin(2, 310, 300), striker(0, 150, 300, 600, 0)})
                     .has_value());
}

TEST(FirstContact, APocketedPieceIsNotTouched) {
    Body gone = coin(1, 300, 300);
    gone.pocketed = true;
    EXPECT_FALSE(contact_of({gone, striker(0, 150, 300, 600, 0)}).has_value());
}

TEST(FirstContact, SameSceneSameAnswerOnAReusedEngine) {
    const PhysicsConfig config;
    ExactEngine engine(config);
    const std::vector<Body> scene{coin(1, 300, 316), coin(2, 420, 280),
                                  striker(0, 150, 300, 600, 10)};
    const auto first = first_contact(engine, scene);
    ASSERT_TRUE(first.has_value());
    (void)first_contact(engine,
                        std::vector<Body>{coin(3, 200, 200), striker(0, 150, 500, 0, -700)});
    EXPECT_EQ(first_contact(engine, scene), first);
}

} // namespace
} // namespace carrom
