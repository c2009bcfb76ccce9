// nearest_legal_shot: the legal shot a room plays for a bot's shot the rules refuse. Standard
// board: the baseline runs from 113 to 487 px, the bottom one at y = 520, the top one at y = 80;
// a striker (18 px) and a coin (14 px) overlap when their centres are under 32 px apart.

#include "rules_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace carrom::rules {
namespace {

using test::broken;
using test::kWhite;
using test::put;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kUp = -std::numbers::pi / 2.0;

void expect_legal(const MatchState& m, int seat, const std::optional<Shot>& shot) {
    ASSERT_TRUE(shot);
    const auto error = check_placement(m, seat, *shot);
    EXPECT_FALSE(error) << error->message;
}

TEST(NearestLegalShot, ALegalShotComesBackUnchanged) {
    const MatchState m = broken(RuleSet::Icf);
    const auto shot = nearest_legal_shot(m, 0, {250.5, 1.25, 7.5});
    expect_legal(m, 0, shot);
    EXPECT_EQ(shot->x_px, 250.5);
    EXPECT_EQ(shot->angle_rad, 1.25);
    EXPECT_EQ(shot->power, 7.5);
}

TEST(NearestLegalShot, OffTheBaselineGoesToItsNearerEnd) {
    const MatchState m = broken(RuleSet::Icf);
    EXPECT_EQ(nearest_legal_shot(m, 0, {-40.0, kUp, 5.0})->x_px, 113.0);
    EXPECT_EQ(nearest_legal_shot(m, 0, {112.9, kUp, 5.0})->x_px, 113.0);
    EXPECT_EQ(nearest_legal_shot(m, 0, {1e9, kUp, 5.0})->x_px, 487.0);
}

TEST(NearestLegalShot, APositionNotFiniteGoesToTheMiddle) {
    const MatchState m = broken(RuleSet::Icf);
    const auto shot = nearest_legal_shot(m, 0, {kNaN, kUp, 5.0});
    expect_legal(m, 0, shot);
    EXPECT_EQ(shot->x_px, 300.0);
    EXPECT_EQ(shot->angle_rad, kUp);
    EXPECT_EQ(nearest_legal_shot(m, 0, {-std::numeric_limits<double>::infinity(), kUp, 5.0})->x_px,
              300.0);
}

TEST(NearestLegalShot, OnAPieceGoesToTheNearestFreePosition) {
    MatchState m = broken(RuleSet::Icf);
    put(m, kWhite, {300.0, 520.0}); // a coin on the bottom baseline
    EXPECT_EQ(check_placement(m, 0, {305.0, kUp, 5.0})->code, RuleErrorCode::StrikerOverlaps);
    // Touching is free: 32 px on either side; the nearer side wins.
    EXPECT_EQ(nearest_legal_shot(m, 0, {305.0, kUp, 5.0})->x_px, 332.0);
    EXPECT_EQ(nearest_legal_shot(m, 0, {290.0, kUp, 5.0})->x_px, 268.0);
    // At equal distance the lower position.
    EXPECT_EQ(nearest_legal_shot(m, 0, {300.0, kUp, 5.0})->x_px, 268.0);
    // The angle and the power stay.
    const auto shot = nearest_legal_shot(m, 0, {301.0, 0.5, 9.0});
    expect_legal(m, 0, shot);
    EXPECT_EQ(shot->angle_rad, 0.5);
    EXPECT_EQ(shot->power, 9.0);
}

TEST(NearestLegalShot, APieceAtTheEndPushesTheStrikerInwards) {
    MatchState m = broken(RuleSet::Icf);
    put(m, kWhite, {113.0, 520.0});
    EXPECT_EQ(nearest_legal_shot(m, 0, {-5.0, kUp, 5.0})->x_px, 145.0);
}

TEST(NearestLegalShot, AnAngleNotFiniteAimsAtTheCentre) {
    const MatchState m = broken(RuleSet::Icf);
    EXPECT_EQ(nearest_legal_shot(m, 0, {300.0, kNaN, 5.0})->angle_rad, kUp);
    EXPECT_EQ(nearest_legal_shot(m, 0, {200.0, kNaN, 5.0})->angle_rad, std::atan2(-220.0, 100.0));
    // Seat 1 of singles shoots from the top: down the board.
    EXPECT_EQ(
        nearest_legal_shot(m, 1, {300.0, std::numeric_limits<double>::infinity(), 5.0})->angle_rad,
        std::numbers::pi / 2.0);
}

TEST(NearestLegalShot, ThePowerIsClampedToItsRange) {
    const MatchState m = broken(RuleSet::Icf);
    EXPECT_EQ(nearest_legal_shot(m, 0, {300.0, kUp, 100.0})->power, m.physics.max_power);
    EXPECT_EQ(nearest_legal_shot(m, 0, {300.0, kUp, -3.0})->power, 0.0);
    EXPECT_EQ(nearest_legal_shot(m, 0, {300.0, kUp, kNaN})->power, 0.0);
}

TEST(NearestLegalShot, ASideSeatOfDoublesSearchesItsOwnBaseline) {
    RulesConfig config = test::no_clock();
    config.seat_count = 4;
    MatchState m = new_match(RuleSet::Icf, config, PhysicsConfig{});
    ASSERT_EQ(m.seats[1].side, Side::Right);
    put(m, kWhite, {520.0, 300.0}); // on the right baseline; x is along it (y on the board)
    const auto shot = nearest_legal_shot(m, 1, {310.0, kNaN, 5.0});
    expect_legal(m, 1, shot);
    EXPECT_EQ(shot->x_px, 332.0);
    EXPECT_EQ(shot->angle_rad, std::atan2(-32.0, -220.0));
}

TEST(NearestLegalShot, NoneForASeatThatDoesNotExist) {
    const MatchState m = broken(RuleSet::Icf);
    EXPECT_FALSE(nearest_legal_shot(m, 2, {300.0, kUp, 5.0}));
    EXPECT_FALSE(nearest_legal_shot(m, -1, {300.0, kUp, 5.0}));
}

TEST(NearestLegalShot, NoneWhenPiecesCoverTheWholeBaseline) {
    MatchState m = broken(RuleSet::Icf);
    int id = 1;
    for (double x = 113.0; x < 487.0 + 28.0; x += 28.0) { // touching coins, 14 of them
        put(m, id++, {x, 520.0});
    }
    EXPECT_FALSE(nearest_legal_shot(m, 0, {300.0, kUp, 5.0}));
    EXPECT_TRUE(nearest_legal_shot(m, 1, {300.0, kUp, 5.0})); // the top baseline is free
}

} // namespace
} // namespace carrom::rules
