#include "carrom/client/screen_mapping.hpp"
#include "carrom/rules/placement.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace carrom::client {
namespace {

void expect_near(Vec2 a, Vec2 b, double tol = 1e-9) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
}

TEST(ScreenLayout, SquareWindowPutsBoardBetweenTheBars) {
    const ScreenLayout l = make_layout(900.0, 900.0);
    EXPECT_DOUBLE_EQ(l.top_bar.h, 68.0);    // 900 * 0.075 = 67.5, rounded to whole px
    EXPECT_DOUBLE_EQ(l.bottom_bar.h, 40.0); // 900 * 0.045 capped at 40
    EXPECT_DOUBLE_EQ(l.board.w, l.board.h);
    EXPECT_DOUBLE_EQ(l.board.h, 900.0 - l.top_bar.h - l.bottom_bar.h);
    EXPECT_DOUBLE_EQ(l.board.y, l.top_bar.h);
    EXPECT_DOUBLE_EQ(l.board.x, (900.0 - l.board.w) / 2.0);
}

TEST(ScreenLayout, EveryRectIsOnWholePixels) {
    for (double w : {333.0, 901.0, 1277.0}) {
        for (double h : {411.0, 899.0, 1001.0}) {
            const ScreenLayout l = make_layout(w, h);
            for (const Rect& r : {l.top_bar, l.board, l.bottom_bar}) {
                EXPECT_EQ(r.x, std::floor(r.x)) << w << "x" << h;
                EXPECT_EQ(r.y, std::floor(r.y)) << w << "x" << h;
                EXPECT_EQ(r.w, std::floor(r.w)) << w << "x" << h;
                EXPECT_EQ(r.h, std::floor(r.h)) << w << "x" << h;
            }
            EXPECT_EQ(l.bottom_bar.y + l.bottom_bar.h, h);
            EXPECT_LE(l.board.y + l.board.h, l.bottom_bar.y);
            EXPECT_GE(l.board.y, l.top_bar.h);
        }
    }
}

TEST(ScreenLayout, WideWindowLetterboxesLeftAndRight) {
    const ScreenLayout l = make_layout(1600.0, 900.0);
    EXPECT_DOUBLE_EQ(l.board.w, l.board.h);
    EXPECT_DOUBLE_EQ(l.board.x, (1600.0 - l.board.w) / 2.0);
    EXPECT_DOUBLE_EQ(l.top_bar.w, 1600.0);
}

TEST(ScreenLayout, TallWindowLetterboxesAboveAndBelow) {
    const ScreenLayout l = make_layout(500.0, 1200.0);
    EXPECT_DOUBLE_EQ(l.board.w, 500.0);
    EXPECT_DOUBLE_EQ(l.board.x, 0.0);
    const double space = 1200.0 - l.top_bar.h - l.bottom_bar.h;
    EXPECT_DOUBLE_EQ(l.board.y, l.top_bar.h + (space - 500.0) / 2.0);
}

TEST(ScreenLayout, BarHeightsStayWithinBounds) {
    EXPECT_DOUBLE_EQ(make_layout(300.0, 300.0).top_bar.h, 40.0);
    EXPECT_DOUBLE_EQ(make_layout(3000.0, 3000.0).top_bar.h, 72.0);
    EXPECT_DOUBLE_EQ(make_layout(300.0, 300.0).bottom_bar.h, 24.0);
}

bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

TEST(ScreenLayout, SideAreaBesideAWideWindowsBoard) {
    const ScreenLayout l = make_layout(1280.0, 900.0, 2, true);
    const double space = 900.0 - l.top_bar.h - l.bottom_bar.h;
    EXPECT_DOUBLE_EQ(l.board.w, space); // the full height still fits
    EXPECT_DOUBLE_EQ(l.side.x, l.board.x + l.board.w + kSideAreaGap);
    EXPECT_DOUBLE_EQ(l.side.w, kSideAreaW);
    EXPECT_DOUBLE_EQ(l.side.h, l.board.h);
    EXPECT_FALSE(overlaps(l.side, l.board));
}

TEST(ScreenLayout, SideAreaUnderASquareWindowsBoard) {
    const ScreenLayout l = make_layout(900.0, 900.0, 2, true);
    EXPECT_DOUBLE_EQ(l.side.y, l.board.y + l.board.h + kSideAreaGap);
    EXPECT_DOUBLE_EQ(l.side.y + l.side.h, l.bottom_bar.y); // no room left under it
    EXPECT_GE(l.side.h, 56.0);
    EXPECT_FALSE(overlaps(l.side, l.board));
    EXPECT_DOUBLE_EQ(l.board.y, l.top_bar.h);
}

TEST(ScreenLayout, NoSideAreaUnlessAsked) {
    EXPECT_DOUBLE_EQ(make_layout(1280.0, 900.0).side.w, 0.0);
}

TEST(ScreenLayout, DegenerateWindowGivesPositiveBoard) {
    const ScreenLayout l = make_layout(0.0, 0.0);
    EXPECT_GT(l.board.w, 0.0);
    EXPECT_GT(make_mapping(l.board, 600.0).scale, 0.0);
}

TEST(ScreenMapping, CornersAndCentreOfTheBoard) {
    const ScreenMapping m = make_mapping({150.0, 60.0, 300.0, 300.0}, 600.0);
    EXPECT_DOUBLE_EQ(m.scale, 0.5);
    expect_near(m.to_screen({0.0, 0.0}), {150.0, 60.0});
    expect_near(m.to_screen({600.0, 600.0}), {450.0, 360.0});
    expect_near(m.to_screen({300.0, 300.0}), {300.0, 210.0});
    expect_near(m.to_board({300.0, 210.0}), {300.0, 300.0});
    EXPECT_DOUBLE_EQ(m.length_to_screen(18.0), 9.0);
    EXPECT_DOUBLE_EQ(m.length_to_board(9.0), 18.0);
}

TEST(ScreenMapping, FlippedViewTurnsTheBoardHalfATurn) {
    const ScreenMapping m = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0, rules::Side::Top);
    // The top baseline (y = 80) appears near the bottom of the window.
    expect_near(m.to_screen({300.0, 80.0}), {300.0, 520.0});
    expect_near(m.to_screen({113.0, 80.0}), {487.0, 520.0});
    expect_near(m.to_board({487.0, 520.0}), {113.0, 80.0});
}

// Each side's own baseline is drawn at the bottom of the window, at the bottom baseline's place
// (y = 520 of a 600 px board drawn 1:1), and the turn keeps the seats' anticlockwise order.
TEST(ScreenMapping, EverySideSeesItsOwnBaselineAtTheBottom) {
    const PhysicsConfig physics;
    using rules::Side;
    for (Side side : {Side::Bottom, Side::Right, Side::Top, Side::Left}) {
        const ScreenMapping m = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0, side);
        for (double along : {113.0, 200.0, 300.0, 487.0}) {
            const Vec2 board = rules::striker_for(physics, side, Shot{along, 0.0, 0.0}).pos_px;
            const Vec2 screen = m.to_screen(board);
            EXPECT_NEAR(screen.y, 520.0, 1e-9) << rules::to_string(side) << " " << along;
            expect_near(m.to_board(screen), board);
        }
        // The next seat anticlockwise (side + 1) sits at the right of the window, the one after
        // at the top, the last at the left.
        const auto side_at = [&](int k) {
            return static_cast<Side>((static_cast<int>(side) + k) % 4);
        };
        EXPECT_NEAR(m.to_screen(rules::striker_for(physics, side_at(1), Shot{}).pos_px).x, 520.0,
                    1e-9);
        EXPECT_NEAR(m.to_screen(rules::striker_for(physics, side_at(2), Shot{}).pos_px).y, 80.0,
                    1e-9);
        EXPECT_NEAR(m.to_screen(rules::striker_for(physics, side_at(3), Shot{}).pos_px).x, 80.0,
                    1e-9);
    }
}

TEST(ScreenMapping, QuarterTurnsPlaceTheCorners) {
    const ScreenMapping right = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0, rules::Side::Right);
    // Board (x, y) at (size - y, x): the top-left corner goes to the top right.
    expect_near(right.to_screen({0.0, 0.0}), {600.0, 0.0});
    expect_near(right.to_screen({600.0, 0.0}), {600.0, 600.0});
    expect_near(right.to_screen({100.0, 250.0}), {350.0, 100.0});
    const ScreenMapping left = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0, rules::Side::Left);
    // Board (x, y) at (y, size - x).
    expect_near(left.to_screen({0.0, 0.0}), {0.0, 600.0});
    expect_near(left.to_screen({100.0, 250.0}), {250.0, 500.0});
}

TEST(ScreenMapping, ScreenRightIsAlongEachOwnBaseline) {
    using rules::Side;
    // Moving right on the screen moves along the own baseline: +x at the bottom, -y on the
    // right side, -x at the top, +y on the left side.
    const std::pair<Side, Vec2> expected[] = {{Side::Bottom, {1.0, 0.0}},
                                              {Side::Right, {0.0, -1.0}},
                                              {Side::Top, {-1.0, 0.0}},
                                              {Side::Left, {0.0, 1.0}}};
    for (const auto& [side, dir] : expected) {
        const ScreenMapping m = make_mapping({20.0, 40.0, 300.0, 300.0}, 600.0, side);
        expect_near(m.direction_to_board({1.0, 0.0}), dir, 1e-12);
    }
}

TEST(ScreenMapping, RoundTripsForAnyWindowSize) {
    using rules::Side;
    for (double w : {320.0, 900.0, 1920.0}) {
        for (double h : {240.0, 900.0, 1080.0}) {
            for (Side side : {Side::Bottom, Side::Right, Side::Top, Side::Left}) {
                const ScreenMapping m = make_mapping(make_layout(w, h).board, 600.0, side);
                for (Vec2 p : {Vec2{0.0, 0.0}, Vec2{113.0, 520.0}, Vec2{599.5, 17.25}}) {
                    expect_near(m.to_board(m.to_screen(p)), p, 1e-9);
                }
            }
        }
    }
}

} // namespace
} // namespace carrom::client
