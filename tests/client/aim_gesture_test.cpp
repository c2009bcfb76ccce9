#include "carrom/client/aim_gesture.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "carrom/rules/match.hpp"
#include "carrom/rules/placement.hpp"
#include "client/aim_support.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client {
namespace {

using test::kEmpty;
using test::kPi;

using rules::Side;

TEST(AimController, RightBaselineSlidesAlongYAndShootsIntoTheBoard) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(Side::Right, 200.0);
    EXPECT_EQ(aim.striker_px(), (Vec2{520.0, 200.0}));
    aim.pointer_down({540.0, 350.0}, kEmpty); // in the band beside the right baseline
    EXPECT_EQ(aim.phase(), AimPhase::Sliding);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 350.0);
    aim.pointer_move({500.0, 900.0}, kEmpty);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 487.0); // clamped to the baseline's range
    aim.pointer_up({500.0, 900.0}, kEmpty);
    aim.nudge(-1, true, kEmpty);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 477.0);
    aim.pointer_down({520.0, 477.0}, kEmpty); // on the striker
    EXPECT_EQ(aim.phase(), AimPhase::Pulling);
    const auto shot = aim.pointer_up({600.0, 477.0}, kEmpty); // pulled back towards the edge
    ASSERT_TRUE(shot.has_value());
    EXPECT_DOUBLE_EQ(shot->x_px, 477.0);
    EXPECT_NEAR(std::abs(shot->angle_rad), kPi, 1e-12); // towards -x, across the board
    EXPECT_DOUBLE_EQ(shot->power, power_from_drag(PhysicsConfig{}, AimConfig{}, 80.0));
}

TEST(AimController, LeftBaselineIgnoresPressesAwayFromIt) {
    AimController aim{PhysicsConfig{}};
    aim.begin_turn(Side::Left, 300.0);
    EXPECT_EQ(aim.striker_px(), (Vec2{80.0, 300.0}));
    aim.pointer_down({300.0, 520.0}, kEmpty); // the bottom baseline is not ours
    EXPECT_EQ(aim.phase(), AimPhase::Idle);
    aim.pointer_down({60.0, 150.0}, kEmpty);
    EXPECT_EQ(aim.phase(), AimPhase::Sliding);
    EXPECT_DOUBLE_EQ(aim.striker_x(), 150.0);
}

std::vector<BodyState> pieces_of(const rules::MatchState& state) {
    std::vector<BodyState> out;
    for (const Body& b : state.bodies) {
        out.push_back({b.id, b.kind, b.pos_px, b.vel_px_s, b.pocketed});
    }
    return out;
}

// The --autoplay path from every seat of a doubles match: the gesture's points go to whole
// window px through that seat's turned view and back, into the aim controller, and the shot it
// releases is the chosen one (within a window pixel) and one the rules accept from that seat.
TEST(AimGesture, EverySeatOfDoublesMakesTheChosenShotThroughItsTurnedView) {
    const PhysicsConfig physics;
    rules::RulesConfig config;
    config.seat_count = 4;
    const rules::MatchState state = rules::new_match(rules::RuleSet::Icf, config, physics);
    ASSERT_EQ(state.seats.size(), 4u);
    const std::vector<BodyState> pieces = pieces_of(state);
    const Rect board = make_layout(900.0, 900.0, 4).board;
    const double px = 600.0 / board.w; // board px per window px
    for (const rules::Seat& seat : state.seats) {
        const ScreenMapping view = make_mapping(board, 600.0, seat.side);
        // Into the board from each side: up from the bottom, -x from the right, down from the
        // top, +x from the left.
        const double inward =
            std::array{-kPi / 2.0, kPi, kPi / 2.0, 0.0}[static_cast<int>(seat.side)];
        for (const double x : {130.0, 300.0, 470.0}) {
            for (const double turn : {-0.4, 0.0, 0.3}) {
                const Shot chosen{x, std::remainder(inward + turn, 2.0 * kPi), 14.0};
                AimController aim{physics};
                aim.begin_turn(seat.side, 300.0);
                std::optional<ShotIntent> made;
                for (const GestureStep& step :
                     shot_gesture(physics, AimConfig{}, seat.side, 300.0, chosen)) {
                    const Vec2 s = view.to_screen(step.board_px);
                    const Vec2 p = view.to_board({std::round(s.x), std::round(s.y)});
                    switch (step.kind) {
                    case GestureStep::Kind::Press:
                        aim.pointer_down(p, pieces);
                        break;
                    case GestureStep::Kind::Move:
                        aim.pointer_move(p, pieces);
                        break;
                    case GestureStep::Kind::Release:
                        made = aim.pointer_up(p, pieces);
                        break;
                    }
                }
                SCOPED_TRACE(std::string(rules::to_string(seat.side)) + " x " + std::to_string(x) +
                             " turn " + std::to_string(turn));
                ASSERT_TRUE(made.has_value());
                EXPECT_NEAR(made->x_px, x, px);
                EXPECT_NEAR(std::remainder(made->angle_rad - chosen.angle_rad, 2.0 * kPi), 0.0,
                            0.02);
                EXPECT_NEAR(made->power, chosen.power, 0.2);
                const Shot shot{made->x_px, made->angle_rad, made->power};
                EXPECT_FALSE(rules::check_placement(state, seat.index, shot).has_value());
                // The striker the server would place is where the controller showed it.
                const Vec2 placed = rules::striker_for(physics, seat.side, shot).pos_px;
                EXPECT_NEAR(placed.x, aim.striker_px().x, 1e-9);
                EXPECT_NEAR(placed.y, aim.striker_px().y, 1e-9);
            }
        }
    }
}

} // namespace
} // namespace carrom::client
