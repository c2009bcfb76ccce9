#pragma once
// The markings of a carrom board, derived from the physics config so that what is drawn matches
// what the server simulates. Board px, origin at the board's top-left corner, y down.
// Proportions follow the ICF board (docs/client.md, "Board drawing").

#include "carrom/config.hpp"
#include "carrom/vec2.hpp"

#include <array>

namespace carrom::client {

// One side's baseline: two parallel lines bracketing the line the striker centre sits on, with a
// base circle at each end. For the bottom and top sides the lines run along x; for the left and
// right sides along y.
struct BaselineMarking {
    Vec2 start_px{};          // centre line start (first end circle centre)
    Vec2 end_px{};            // centre line end (second end circle centre)
    Vec2 normal{};            // unit vector across the lines (towards the board centre)
    double half_gap_px = 0.0; // each line lies half_gap_px from the centre line
    double end_circle_r_px = 0.0;
};

// A diagonal arrow from near a pocket towards the centre, with an arc at its inner end.
struct ArrowMarking {
    Vec2 tip_px{};  // arrowhead end, near the pocket
    Vec2 tail_px{}; // inner end, towards the centre
    double head_px = 0.0;
    double arc_r_px = 0.0; // radius of the arc around the tail
};

struct BoardGeometry {
    double board_size_px = 600.0;
    double frame_px = 35.0;
    double pocket_r_px = 22.0;
    double coin_r_px = 14.0;
    double striker_r_px = 18.0;
    std::array<Vec2, 4> pockets{}; // top-left, top-right, bottom-left, bottom-right
    Vec2 centre{};
    double centre_circle_r_px = 0.0;            // the small circle the queen sits on
    double outer_circle_r_px = 0.0;             // the circle around the starting layout
    std::array<BaselineMarking, 4> baselines{}; // bottom, top, left, right
    std::array<ArrowMarking, 4> arrows{};       // same order as pockets
};

BoardGeometry make_board_geometry(const PhysicsConfig& config);

// Index of the pocket whose centre is nearest to p.
int nearest_pocket(const BoardGeometry& geometry, Vec2 p);

} // namespace carrom::client
