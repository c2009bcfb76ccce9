// AimAssist: the desktop client's first-contact guide on a board as the client holds it, from the
// exact engine (carrom::first_contact), with the striker placed as the server's rules place it.
#include "carrom/client/aim_assist.hpp"

#include "carrom/rules/placement.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

namespace carrom::client {
namespace {

constexpr double kUp = -std::numbers::pi / 2.0;

BodyState coin(int id, double x, double y) {
    return {id, BodyKind::Black, {x, y}, {}, false};
}

TEST(AimAssist, StraightUpTouchesTheCoinAbove) {
    AimAssist assist{PhysicsConfig{}};
    const std::vector<BodyState> board{coin(1, 300, 300)};
    const auto c = assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 1);
    EXPECT_NEAR(c->striker_px.x, 300.0, 1e-9);
    EXPECT_NEAR(c->striker_px.y, 332.0, 1e-9);
    EXPECT_NEAR(c->piece_direction.x, 0.0, 1e-12);
    EXPECT_NEAR(c->piece_direction.y, -1.0, 1e-12);
}

TEST(AimAssist, TheStrikerStartsWhereTheRulesPlaceIt) {
    const PhysicsConfig physics;
    AimAssist assist{physics};
    const std::vector<BodyState> board{coin(1, 200, 300)};
    const Shot shot{200.0, kUp, 20.0};
    const auto c = assist.guide(board, rules::Side::Bottom, shot);
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->striker_px.x, rules::striker_for(physics, rules::Side::Bottom, shot).pos_px.x);
}

TEST(AimAssist, AStrikerOnTheBoardIsReplacedByTheShots) {
    AimAssist assist{PhysicsConfig{}};
    std::vector<BodyState> board{coin(1, 300, 300)};
    board.push_back({kStrikerId, BodyKind::Striker, {100, 520}, {}, false});
    const auto c = assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 1);
}

TEST(AimAssist, AimingBesideEveryCoinTouchesNothing) {
    AimAssist assist{PhysicsConfig{}};
    const std::vector<BodyState> board{coin(1, 450, 300)};
    EXPECT_FALSE(assist.guide(board, rules::Side::Bottom, {150.0, kUp, 4.0}).has_value());
}

TEST(AimAssist, PocketedCoinsAreIgnored) {
    AimAssist assist{PhysicsConfig{}};
    BodyState gone = coin(1, 300, 300);
    gone.pocketed = true;
    const std::vector<BodyState> board{gone, coin(2, 300, 200)};
    const auto c = assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0});
    ASSERT_TRUE(c.has_value());
    EXPECT_EQ(c->piece_id, 2);
}

TEST(AimAssist, AnOverlappingPlacementHasNoGuide) {
    AimAssist assist{PhysicsConfig{}};
    const std::vector<BodyState> board{coin(1, 300, 520)};
    EXPECT_FALSE(assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0}).has_value());
}

TEST(AimAssist, TheTopSeatAimsDown) {
    AimAssist assist{PhysicsConfig{}};
    const std::vector<BodyState> board{coin(1, 300, 300)};
    const auto c = assist.guide(board, rules::Side::Top, {300.0, -kUp, 20.0});
    ASSERT_TRUE(c.has_value());
    EXPECT_NEAR(c->striker_px.y, 268.0, 1e-9);
    EXPECT_NEAR(c->piece_direction.y, 1.0, 1e-12);
}

TEST(AimAssist, TheSameQuestionRunsTheEngineOnce) {
    AimAssist assist{PhysicsConfig{}};
    const std::vector<BodyState> board{coin(1, 300, 300)};
    const auto first = assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0});
    const auto again = assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0});
    EXPECT_EQ(assist.runs(), 1);
    EXPECT_EQ(first, again);
}

TEST(AimAssist, AnotherShotRunsItAgain) {
    AimAssist assist{PhysicsConfig{}};
    const std::vector<BodyState> board{coin(1, 300, 300)};
    (void)assist.guide(board, rules::Side::Bottom, {300.0, kUp, 20.0});
    const auto c = assist.guide(board, rules::Side::Bottom, {300.0, kUp + 0.05, 20.0});
    EXPECT_EQ(assist.runs(), 2);
    ASSERT_TRUE(c.has_value());
    // The striker drifts right of the coin's centre: the coin goes up and to the left.
    EXPECT_LT(c->piece_direction.x, 0.0);
    EXPECT_LT(c->piece_direction.y, 0.0);
}

} // namespace
} // namespace carrom::client
