#include "carrom/client/screen_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

ScreenLayout make_layout(double window_w, double window_h, int seats, bool side_area) {
    // Whole window px everywhere, so cached layers are copied pixel for pixel, without seams.
    const double w = std::max(std::round(window_w), 1.0);
    const double h = std::max(std::round(window_h), 1.0);
    const double top = std::round(std::clamp(h * 0.075, 40.0, 72.0));
    const double bottom = std::round(std::clamp(h * 0.045, 24.0, 40.0));
    const double seat_h = seats > 2 ? top : 0.0;
    const double space_h = std::max(h - top - bottom - seat_h, 1.0);
    double side = std::min(w, space_h);
    ScreenLayout layout;
    layout.top_bar = {0.0, 0.0, w, top};
    layout.bottom_bar = {0.0, h - bottom, w, bottom};
    layout.seat_bar = {0.0, h - bottom - seat_h, w, seat_h};
    if (side_area) {
        const double beside =
            std::floor(std::max(std::min(space_h, w - kSideAreaW - kSideAreaGap), 1.0));
        const double under_h = std::round(std::clamp(space_h * 0.1, 56.0, 110.0));
        const double under =
            std::floor(std::max(std::min(w, space_h - under_h - kSideAreaGap), 1.0));
        if (beside >= under) {
            // The board and the side area as one block, centred.
            const double x0 = std::floor((w - beside - kSideAreaGap - kSideAreaW) / 2.0);
            const double y0 = top + std::floor((space_h - beside) / 2.0);
            layout.board = {x0, y0, beside, beside};
            layout.side = {x0 + beside + kSideAreaGap, y0, kSideAreaW, beside};
        } else {
            const double x0 = std::floor((w - under) / 2.0);
            layout.board = {x0, top, under, under};
            layout.side = {x0, top + under + kSideAreaGap, under,
                           std::max(space_h - under - kSideAreaGap, 0.0)};
        }
        return layout;
    }
    layout.board = {std::floor((w - side) / 2.0), top + std::floor((space_h - side) / 2.0), side,
                    side};
    return layout;
}

namespace {

// p turned by `quarters` quarter turns about the board centre, clockwise on the screen (y down):
// one turn takes (dx, dy) from the centre to (-dy, dx). Exact (negations and swaps only).
Vec2 turned(Vec2 p, int quarters, double board_size_px) {
    const double c = board_size_px / 2.0;
    Vec2 d{p.x - c, p.y - c};
    for (int i = 0; i < (quarters % 4 + 4) % 4; ++i) {
        d = {-d.y, d.x};
    }
    return {c + d.x, c + d.y};
}

} // namespace

ScreenMapping make_mapping(const Rect& board_rect, double board_size_px, rules::Side bottom) {
    ScreenMapping m;
    m.origin_x = board_rect.x;
    m.origin_y = board_rect.y;
    m.board_size_px = board_size_px;
    m.scale = std::max(std::min(board_rect.w, board_rect.h), 1e-6) / board_size_px;
    m.bottom = bottom;
    return m;
}

Vec2 ScreenMapping::to_screen(Vec2 board_px) const {
    const Vec2 p = turned(board_px, static_cast<int>(bottom), board_size_px);
    return {origin_x + p.x * scale, origin_y + p.y * scale};
}

Vec2 ScreenMapping::to_board(Vec2 window_px) const {
    const Vec2 p{(window_px.x - origin_x) / scale, (window_px.y - origin_y) / scale};
    return turned(p, 4 - static_cast<int>(bottom), board_size_px);
}

Vec2 ScreenMapping::direction_to_board(Vec2 window_dir) const {
    const Vec2 o{origin_x, origin_y};
    return (to_board(o + window_dir) - to_board(o)) * scale;
}

} // namespace carrom::client
