#include "carrom/client/aim_controller.hpp"
#include "client/aim_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace carrom::client {
namespace {

using test::kEmpty;
using test::kPi;

TEST(BaselineClamp, ClampsToTheLegalRange) {
    const PhysicsConfig c;
    EXPECT_DOUBLE_EQ(clamp_baseline_x(c, 300.0), 300.0);
    EXPECT_DOUBLE_EQ(clamp_baseline_x(c, 50.0), 113.0);
    EXPECT_DOUBLE_EQ(clamp_baseline_x(c, 1e9), 487.0);
    EXPECT_DOUBLE_EQ(clamp_baseline_x(c, 113.0), 113.0);
    EXPECT_DOUBLE_EQ(clamp_baseline_x(c, std::nan("")), 300.0);
}

TEST(PowerFromDrag, DeadZoneLinearAndCapped) {
    const PhysicsConfig c;
    AimConfig a;
    a.dead_zone_px = 10.0;
    a.full_power_drag_px = 110.0;
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, 9.99), 0.0);
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, 10.0), 0.0);
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, 60.0), 12.5);
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, 110.0), 25.0);
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, 500.0), 25.0);
    EXPECT_DOUBLE_EQ(power_from_drag(c, a, std::nan("")), 0.0);
}

TEST(Placement, OverlapWithAPieceIsIllegal) {
    const PhysicsConfig c;
    std::vector<BodyState> pieces{{7, BodyKind::White, {300.0, 488.0}, {}, false}};
    // 18 + 14 = 32 px apart is touching, not overlapping.
    EXPECT_TRUE(check_placement(c, {300.0, 520.0}, pieces).legal);
    const Placement p = check_placement(c, {300.0, 519.0}, pieces);
    EXPECT_FALSE(p.legal);
    EXPECT_EQ(p.blocking_id, 7);
    pieces[0].pocketed = true;
    EXPECT_TRUE(check_placement(c, {300.0, 519.0}, pieces).legal);
    // The striker itself never blocks.
    const std::vector<BodyState> striker{{19, BodyKind::Striker, {300.0, 520.0}, {}, false}};
    EXPECT_TRUE(check_placement(c, {300.0, 520.0}, striker).legal);
}

TEST(AimController, TakesNoInputOutsideOurTurn) {
    AimController aim{PhysicsConfig{}};
    aim.pointer_down({300.0, 520.0}, kEmpty);
    EXPECT_EQ(aim.phase(), AimPhase::Inactive);
    EXPECT_FALSE(aim.pointer_up({300.0, 600.0}, kEmpty).has_value());
}

TEST(AimController, PullBackShootsAwayFromThePointer) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.pointer_down({302.0, 521.0}, kEmpty); // on the striker
    EXPECT_EQ(aim.phase(), AimPhase::Pulling);
    aim.pointer_move({300.0, 600.0}, kEmpty);
    const auto shot = aim.pointer_up({300.0, 600.0}, kEmpty);
    ASSERT_TRUE(shot.has_value());
    EXPECT_DOUBLE_EQ(shot->x_px, 300.0);
    EXPECT_NEAR(shot->angle_rad, -kPi / 2.0, 1e-12); // straight up the board
    EXPECT_DOUBLE_EQ(shot->power, power_from_drag(PhysicsConfig{}, AimConfig{}, 80.0));
    EXPECT_EQ(aim.phase(), AimPhase::Idle);
}

TEST(AimController, TopBaselineShotsGoDown) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Top, 200.0);
    EXPECT_EQ(aim.striker_px(), (Vec2{200.0, 80.0}));
    aim.pointer_down({200.0, 80.0}, kEmpty);
    const auto shot = aim.pointer_up({160.0, 40.0}, kEmpty);
    ASSERT_TRUE(shot.has_value());
    EXPECT_NEAR(shot->angle_rad, kPi / 4.0, 1e-12);
}

TEST(AimController, FullPullIsMaxPower) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.pointer_down({300.0, 520.0}, kEmpty);
    aim.pointer_move({300.0, 1000.0}, kEmpty);
    EXPECT_DOUBLE_EQ(aim.power_fraction(), 1.0);
    EXPECT_DOUBLE_EQ(aim.pointer_up({300.0, 1000.0}, kEmpty)->power, 25.0);
}

TEST(AimController, ShortPullIsNoShot) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.pointer_down({300.0, 520.0}, kEmpty);
    EXPECT_FALSE(aim.pointer_up({300.0, 525.0}, kEmpty).has_value());
}

TEST(AimController, EscapeCancelsThePull) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.pointer_down({300.0, 520.0}, kEmpty);
    aim.pointer_move({300.0, 620.0}, kEmpty);
    aim.cancel();
    EXPECT_EQ(aim.phase(), AimPhase::Idle);
    EXPECT_FALSE(aim.pointer_up({300.0, 620.0}, kEmpty).has_value());
}

TEST(AimController, SlidingFollowsThePointerClamped) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    EXPECT_FALSE(aim.take_moved());
    aim.pointer_down({250.0, 530.0}, kEmpty); // in the band, off the striker
    EXPECT_EQ(aim.phase(), AimPhase::Sliding);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 250.0);
    aim.pointer_move({20.0, 700.0}, kEmpty);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 113.0);
    EXPECT_FALSE(aim.pointer_up({20.0, 700.0}, kEmpty).has_value());
    EXPECT_EQ(aim.phase(), AimPhase::Idle);
    EXPECT_TRUE(aim.take_moved());
    EXPECT_FALSE(aim.take_moved());
}

TEST(AimController, PressFarFromTheBaselineDoesNothing) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.pointer_down({250.0, 300.0}, kEmpty);
    EXPECT_EQ(aim.phase(), AimPhase::Idle);
}

TEST(AimController, ArrowKeysStepAndClamp) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.nudge(+1, false, kEmpty);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 301.0);
    aim.nudge(-1, true, kEmpty);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 291.0);
    for (int i = 0; i < 100; ++i) {
        aim.nudge(+1, true, kEmpty);
    }
    EXPECT_DOUBLE_EQ(aim.striker_x(), 487.0);
}

TEST(AimController, IllegalPlacementIsShownAndNeverShoots) {
    const std::vector<BodyState> pieces{{3, BodyKind::Black, {320.0, 510.0}, {}, false}};
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 200.0);
    EXPECT_TRUE(aim.placement().legal);
    aim.pointer_down({300.0, 540.0}, pieces); // slide onto the coin
    EXPECT_FALSE(aim.placement().legal);
    EXPECT_EQ(aim.placement().blocking_id, 3);
    aim.pointer_up({300.0, 540.0}, pieces);
    aim.pointer_down({300.0, 520.0}, pieces);
    EXPECT_EQ(aim.phase(), AimPhase::Pulling);
    EXPECT_FALSE(aim.pointer_up({300.0, 640.0}, pieces).has_value());
    aim.nudge(-1, true, pieces);
    aim.nudge(-1, true, pieces);
    aim.nudge(-1, true, pieces);
    aim.nudge(-1, true, pieces);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 260.0);
    EXPECT_TRUE(aim.placement().legal); // 60 px left of the coin's centre: clear
}

TEST(AimController, NonFinitePointerIsIgnored) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(rules::Side::Bottom, 300.0);
    aim.pointer_down({std::nan(""), 520.0}, kEmpty);
    EXPECT_EQ(aim.phase(), AimPhase::Idle);
}

} // namespace
} // namespace carrom::client
