#include "carrom/client/screen_mapping.hpp"

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

TEST(ScreenLayout, DegenerateWindowGivesPositiveBoard) {
    const ScreenLayout l = make_layout(0.0, 0.0);
    EXPECT_GT(l.board.w, 0.0);
    EXPECT_GT(make_mapping(l.board, 600.0, false).scale, 0.0);
}

TEST(ScreenMapping, CornersAndCentreOfTheBoard) {
    const ScreenMapping m = make_mapping({150.0, 60.0, 300.0, 300.0}, 600.0, false);
    EXPECT_DOUBLE_EQ(m.scale, 0.5);
    expect_near(m.to_screen({0.0, 0.0}), {150.0, 60.0});
    expect_near(m.to_screen({600.0, 600.0}), {450.0, 360.0});
    expect_near(m.to_screen({300.0, 300.0}), {300.0, 210.0});
    expect_near(m.to_board({300.0, 210.0}), {300.0, 300.0});
    EXPECT_DOUBLE_EQ(m.length_to_screen(18.0), 9.0);
    EXPECT_DOUBLE_EQ(m.length_to_board(9.0), 18.0);
}

TEST(ScreenMapping, FlippedViewTurnsTheBoardHalfATurn) {
    const ScreenMapping m = make_mapping({0.0, 0.0, 600.0, 600.0}, 600.0, true);
    // The top baseline (y = 80) appears near the bottom of the window.
    expect_near(m.to_screen({300.0, 80.0}), {300.0, 520.0});
    expect_near(m.to_screen({113.0, 80.0}), {487.0, 520.0});
    expect_near(m.to_board({487.0, 520.0}), {113.0, 80.0});
}

TEST(ScreenMapping, RoundTripsForAnyWindowSize) {
    for (double w : {320.0, 900.0, 1920.0}) {
        for (double h : {240.0, 900.0, 1080.0}) {
            for (bool flipped : {false, true}) {
                const ScreenMapping m = make_mapping(make_layout(w, h).board, 600.0, flipped);
                for (Vec2 p : {Vec2{0.0, 0.0}, Vec2{113.0, 520.0}, Vec2{599.5, 17.25}}) {
                    expect_near(m.to_board(m.to_screen(p)), p, 1e-9);
                }
            }
        }
    }
}

} // namespace
} // namespace carrom::client
