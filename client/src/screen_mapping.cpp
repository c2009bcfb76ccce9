#include "carrom/client/screen_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

ScreenLayout make_layout(double window_w, double window_h) {
    // Whole window px everywhere, so cached layers are copied pixel for pixel, without seams.
    const double w = std::max(std::round(window_w), 1.0);
    const double h = std::max(std::round(window_h), 1.0);
    const double top = std::round(std::clamp(h * 0.075, 40.0, 72.0));
    const double bottom = std::round(std::clamp(h * 0.045, 24.0, 40.0));
    const double space_h = std::max(h - top - bottom, 1.0);
    const double side = std::min(w, space_h);
    ScreenLayout layout;
    layout.top_bar = {0.0, 0.0, w, top};
    layout.bottom_bar = {0.0, h - bottom, w, bottom};
    layout.board = {std::floor((w - side) / 2.0), top + std::floor((space_h - side) / 2.0), side,
                    side};
    return layout;
}

ScreenMapping make_mapping(const Rect& board_rect, double board_size_px, bool flipped) {
    ScreenMapping m;
    m.origin_x = board_rect.x;
    m.origin_y = board_rect.y;
    m.board_size_px = board_size_px;
    m.scale = std::max(std::min(board_rect.w, board_rect.h), 1e-6) / board_size_px;
    m.flipped = flipped;
    return m;
}

Vec2 ScreenMapping::to_screen(Vec2 board_px) const {
    const Vec2 p =
        flipped ? Vec2{board_size_px - board_px.x, board_size_px - board_px.y} : board_px;
    return {origin_x + p.x * scale, origin_y + p.y * scale};
}

Vec2 ScreenMapping::to_board(Vec2 window_px) const {
    const Vec2 p{(window_px.x - origin_x) / scale, (window_px.y - origin_y) / scale};
    return flipped ? Vec2{board_size_px - p.x, board_size_px - p.y} : p;
}

} // namespace carrom::client
