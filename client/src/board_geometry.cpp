#include "carrom/client/board_geometry.hpp"

#include <cmath>
#include <limits>

namespace carrom::client {
namespace {

// Baseline centre lines (where the striker centre sits), one per side. The bottom and top ones
// are the rule baselines of scene.hpp (baseline_y, baseline_x_min/max); left and right are the
// same lines turned a quarter, as on a real board.
std::array<BaselineMarking, 4> make_baselines(const PhysicsConfig& c) {
    const double near = c.baseline_offset_px;
    const double far = c.board_size_px - c.baseline_offset_px;
    const double lo = c.frame_px + c.baseline_end_margin_px + c.striker_radius_px;
    const double hi = c.board_size_px - lo;
    // ICF: the gap between the two lines is 0.77 of the striker diameter; the base circle
    // touches both lines. With the default geometry this makes the half gap one coin radius.
    const double half_gap = 0.77 * c.striker_radius_px;
    std::array<BaselineMarking, 4> out{};
    out[0] = {{lo, far}, {hi, far}, {0.0, -1.0}, half_gap, half_gap};
    out[1] = {{lo, near}, {hi, near}, {0.0, 1.0}, half_gap, half_gap};
    out[2] = {{near, lo}, {near, hi}, {1.0, 0.0}, half_gap, half_gap};
    out[3] = {{far, lo}, {far, hi}, {-1.0, 0.0}, half_gap, half_gap};
    return out;
}

ArrowMarking make_arrow(Vec2 pocket, Vec2 centre, const PhysicsConfig& c) {
    const Vec2 d = centre - pocket;
    const Vec2 dir = d * (1.0 / length(d));
    ArrowMarking a;
    a.tip_px = pocket + dir * (c.pocket_radius_px + 1.2 * c.coin_radius_px);
    a.tail_px = pocket + dir * (c.pocket_radius_px + 10.5 * c.coin_radius_px);
    a.head_px = 0.6 * c.coin_radius_px;
    a.arc_r_px = 1.3 * c.coin_radius_px;
    return a;
}

} // namespace

BoardGeometry make_board_geometry(const PhysicsConfig& config) {
    BoardGeometry g;
    g.board_size_px = config.board_size_px;
    g.frame_px = config.frame_px;
    g.pocket_r_px = config.pocket_radius_px;
    g.coin_r_px = config.coin_radius_px;
    g.striker_r_px = config.striker_radius_px;
    g.pockets = config.pocket_centres();
    g.centre = config.centre();
    g.centre_circle_r_px = config.coin_radius_px;
    // The starting layout's outer ring reaches 4.5 r + r from the centre; the circle encloses it.
    g.outer_circle_r_px = 6.0 * config.coin_radius_px;
    g.baselines = make_baselines(config);
    for (std::size_t i = 0; i < g.pockets.size(); ++i) {
        g.arrows[i] = make_arrow(g.pockets[i], g.centre, config);
    }
    return g;
}

int nearest_pocket(const BoardGeometry& geometry, Vec2 p) {
    int best = 0;
    double best_d2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < geometry.pockets.size(); ++i) {
        const double d2 = length_squared(p - geometry.pockets[i]);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = static_cast<int>(i);
        }
    }
    return best;
}

} // namespace carrom::client
