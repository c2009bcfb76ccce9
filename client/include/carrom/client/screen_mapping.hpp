#pragma once
// Where the board and the HUD go in a window of any size, and the mapping between board px and
// window px. The board is a letterboxed square (uniform scale, centred in the space left by the
// HUD bars). Every player sees the board turned so that their own baseline is at the bottom of
// their window: a quarter turn for the right seat of doubles, half a turn for the top seat, three
// quarters for the left seat (spectators see seat 0's view, the board as it is).

#include "carrom/rules/seat.hpp"
#include "carrom/vec2.hpp"

namespace carrom::client {

struct Rect {
    double x = 0.0;
    double y = 0.0;
    double w = 0.0;
    double h = 0.0;
    bool contains(Vec2 p) const { return p.x >= x && p.x < x + w && p.y >= y && p.y < y + h; }
    bool operator==(const Rect&) const = default; // exactly the same place and size
};

struct ScreenLayout {
    Rect top_bar;    // singles: names, scores, turn, shot clock; doubles: the seats left, across
                     // and right of ours, each at its side of the turned board
    Rect board;      // square, where the board is drawn
    Rect seat_bar;   // doubles: our seat (the bottom one) with the turn, shot clock and queen;
                     // singles: empty (h = 0) at the bottom bar's top
    Rect bottom_bar; // rule set, connection, messages
    // With a side area (the match window): the message log and the first-game tips, beside the
    // board (right of it) or under it, never over it; else empty (w = h = 0).
    Rect side;
};

// Bar heights scale with the window height within fixed bounds (window px). Every rect is on
// whole window px (the board texture and the HUD layers are copied pixel for pixel). A room of
// four seats gets a seat bar as high as the top bar between the board and the bottom bar.
// With side_area the board also leaves room for `side`: beside it (kSideAreaW px wide) or under it
// (a tenth of the space between the bars, 56 to 110 px), whichever leaves the bigger board
// (beside on a tie), as the web page does (web/js/side_layout.js).
ScreenLayout make_layout(double window_w, double window_h, int seats = 2, bool side_area = false);
inline constexpr double kSideAreaW = 240.0;
inline constexpr double kSideAreaGap = 10.0;

// Board px <-> window px. Invariant: scale > 0.
struct ScreenMapping {
    double origin_x = 0.0; // window px of the board's top-left corner (as drawn)
    double origin_y = 0.0;
    double scale = 1.0; // window px per board px
    double board_size_px = 600.0;
    // The side of the board drawn at the bottom of the window. The board is turned by that
    // side's index (rules::Side: bottom 0, right 1, top 2, left 3) quarter turns, clockwise on
    // the screen, about its centre: right puts board (x, y) at (size - y, x), top at
    // (size - x, size - y), left at (y, size - x).
    rules::Side bottom = rules::Side::Bottom;

    Vec2 to_screen(Vec2 board_px) const;
    Vec2 to_board(Vec2 window_px) const;
    // A direction in the window (e.g. screen right, {1, 0}) as a board direction.
    Vec2 direction_to_board(Vec2 window_dir) const;
    // Lengths (radii, line widths) are only scaled.
    double length_to_screen(double board_len) const { return board_len * scale; }
    double length_to_board(double window_len) const { return window_len / scale; }
};

ScreenMapping make_mapping(const Rect& board_rect, double board_size_px,
                           rules::Side bottom = rules::Side::Bottom);

} // namespace carrom::client
