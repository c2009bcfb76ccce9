#pragma once
// Where the board and the HUD go in a window of any size, and the mapping between board px and
// window px. The board is a letterboxed square (uniform scale, centred in the space left by the
// HUD bars). A seat that shoots from the top baseline sees the board turned half a turn, so that
// every player's own baseline is at the bottom of their window.

#include "carrom/vec2.hpp"

namespace carrom::client {

struct Rect {
    double x = 0.0;
    double y = 0.0;
    double w = 0.0;
    double h = 0.0;
    bool contains(Vec2 p) const { return p.x >= x && p.x < x + w && p.y >= y && p.y < y + h; }
};

struct ScreenLayout {
    Rect top_bar;    // names, scores, turn, shot clock
    Rect board;      // square, where the board is drawn
    Rect bottom_bar; // rule set, connection, messages
};

// Bar heights scale with the window height within fixed bounds (window px). Every rect is on
// whole window px (the board texture and the HUD layers are copied pixel for pixel).
ScreenLayout make_layout(double window_w, double window_h);

// Board px <-> window px. Invariant: scale > 0.
struct ScreenMapping {
    double origin_x = 0.0; // window px of the board's top-left corner (as drawn)
    double origin_y = 0.0;
    double scale = 1.0; // window px per board px
    double board_size_px = 600.0;
    bool flipped = false; // half a turn: board (x, y) appears at (size - x, size - y)

    Vec2 to_screen(Vec2 board_px) const;
    Vec2 to_board(Vec2 window_px) const;
    // Lengths (radii, line widths) are only scaled.
    double length_to_screen(double board_len) const { return board_len * scale; }
    double length_to_board(double window_len) const { return window_len / scale; }
};

ScreenMapping make_mapping(const Rect& board_rect, double board_size_px, bool flipped);

} // namespace carrom::client
