#include "carrom/client/board_geometry.hpp"
#include "carrom/scene.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

TEST(BoardGeometry, BottomAndTopBaselinesAreTheRuleBaselines) {
    const PhysicsConfig c;
    const BoardGeometry g = make_board_geometry(c);
    EXPECT_DOUBLE_EQ(g.baselines[0].start_px.y, baseline_y(c, Baseline::Bottom));
    EXPECT_DOUBLE_EQ(g.baselines[1].start_px.y, baseline_y(c, Baseline::Top));
    EXPECT_DOUBLE_EQ(g.baselines[0].start_px.x, baseline_x_min(c));
    EXPECT_DOUBLE_EQ(g.baselines[0].end_px.x, baseline_x_max(c));
    EXPECT_DOUBLE_EQ(g.baselines[0].start_px.x, 113.0);
    EXPECT_DOUBLE_EQ(g.baselines[0].end_px.x, 487.0);
    EXPECT_DOUBLE_EQ(g.baselines[0].start_px.y, 520.0);
    EXPECT_DOUBLE_EQ(g.baselines[1].start_px.y, 80.0);
}

TEST(BoardGeometry, SideBaselinesAreTheSameLinesTurned) {
    const BoardGeometry g = make_board_geometry(PhysicsConfig{});
    EXPECT_DOUBLE_EQ(g.baselines[2].start_px.x, 80.0);
    EXPECT_DOUBLE_EQ(g.baselines[2].start_px.y, 113.0);
    EXPECT_DOUBLE_EQ(g.baselines[3].end_px.x, 520.0);
    EXPECT_DOUBLE_EQ(g.baselines[3].end_px.y, 487.0);
    for (const BaselineMarking& b : g.baselines) {
        EXPECT_DOUBLE_EQ(b.end_circle_r_px, b.half_gap_px); // the circle touches both lines
        EXPECT_DOUBLE_EQ(length(b.normal), 1.0);
    }
}

TEST(BoardGeometry, PocketsAndCentreFollowTheConfig) {
    PhysicsConfig c;
    c.board_size_px = 800.0;
    c.frame_px = 40.0;
    const BoardGeometry g = make_board_geometry(c);
    EXPECT_EQ(g.pockets[0], (Vec2{62.0, 62.0}));
    EXPECT_EQ(g.pockets[3], (Vec2{738.0, 738.0}));
    EXPECT_EQ(g.centre, (Vec2{400.0, 400.0}));
    // The outer circle encloses the starting layout (outer ring at 4.5 r, plus r).
    EXPECT_GT(g.outer_circle_r_px, 5.5 * c.coin_radius_px);
}

TEST(BoardGeometry, ArrowsRunFromNearThePocketTowardsTheCentre) {
    const BoardGeometry g = make_board_geometry(PhysicsConfig{});
    for (std::size_t i = 0; i < 4; ++i) {
        const ArrowMarking& a = g.arrows[i];
        EXPECT_LT(length(a.tip_px - g.pockets[i]), length(a.tail_px - g.pockets[i]));
        EXPECT_GT(length(a.tip_px - g.pockets[i]), g.pocket_r_px);
        // On the diagonal.
        EXPECT_NEAR(std::abs(a.tip_px.x - g.centre.x), std::abs(a.tip_px.y - g.centre.y), 1e-9);
        // Clear of the outer circle.
        EXPECT_GT(length(a.tail_px - g.centre), g.outer_circle_r_px);
    }
}

TEST(BoardGeometry, NearestPocket) {
    const BoardGeometry g = make_board_geometry(PhysicsConfig{});
    EXPECT_EQ(nearest_pocket(g, {10.0, 10.0}), 0);
    EXPECT_EQ(nearest_pocket(g, {590.0, 40.0}), 1);
    EXPECT_EQ(nearest_pocket(g, {100.0, 500.0}), 2);
    EXPECT_EQ(nearest_pocket(g, {560.0, 560.0}), 3);
}

} // namespace
} // namespace carrom::client
