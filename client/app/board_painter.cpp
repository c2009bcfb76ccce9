#include "board_painter.hpp"

#include "draw_util.hpp"
#include "text.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

namespace carrom::client::app {
namespace {

constexpr double kPi = std::numbers::pi;

// Smooth value noise in [0, 1] for the wood grain (deterministic).
double hash01(int x, int y) {
    auto h =
        static_cast<std::uint32_t>(x) * 374761393u + static_cast<std::uint32_t>(y) * 668265263u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return static_cast<double>(h ^ (h >> 16)) / 4294967295.0;
}

double value_noise(double x, double y) {
    const int xi = static_cast<int>(std::floor(x));
    const int yi = static_cast<int>(std::floor(y));
    const double fx = x - xi;
    const double fy = y - yi;
    const double sx = fx * fx * (3.0 - 2.0 * fx);
    const double sy = fy * fy * (3.0 - 2.0 * fy);
    const double a = hash01(xi, yi) + (hash01(xi + 1, yi) - hash01(xi, yi)) * sx;
    const double b = hash01(xi, yi + 1) + (hash01(xi + 1, yi + 1) - hash01(xi, yi + 1)) * sx;
    return a + (b - a) * sy;
}

sf::Color shade(double r, double g, double b, double k) {
    auto c = [k](double v) { return static_cast<sf::Uint8>(std::clamp(v * k, 0.0, 255.0)); };
    return {c(r), c(g), c(b)};
}

// Wood: grain runs along `along` (board px), rings across it.
double grain(double along, double across, double seed) {
    const double warp = 6.0 * value_noise(along * 0.01 + seed, across * 0.03);
    const double rings = 0.5 + 0.5 * std::sin((across + warp * 4.0) * 0.55);
    const double fine = value_noise(along * 0.15, across * 1.3 + seed);
    return 0.75 * rings + 0.25 * fine;
}

sf::Color surface_colour(double x, double y) {
    const double g = grain(y, x, 11.0);
    return shade(236.0, 202.0, 148.0, 0.93 + 0.08 * g);
}

sf::Color frame_colour(const BoardGeometry& geo, double x, double y) {
    const double s = geo.board_size_px;
    const double to_edge = std::min(std::min(x, y), std::min(s - x, s - y));
    // Grain runs along each side of the frame.
    const bool horizontal = std::min(y, s - y) < std::min(x, s - x);
    const double g = horizontal ? grain(x, y, 3.0) : grain(y, x, 7.0);
    double k = 0.85 + 0.2 * g;
    const double inner = geo.frame_px - to_edge; // distance to the playing surface
    if (inner < 5.0) {
        k *= 0.7 + 0.06 * inner; // the cushion lip casts a shadow on the frame's inner edge
    }
    if (to_edge < 3.0) {
        k *= 0.75; // outer edge
    }
    return shade(118.0, 62.0, 30.0, k);
}

void paint_wood(sf::Image& image, const BoardGeometry& geo, unsigned side) {
    const double px_to_board = geo.board_size_px / static_cast<double>(side);
    for (unsigned j = 0; j < side; ++j) {
        for (unsigned i = 0; i < side; ++i) {
            const double x = (i + 0.5) * px_to_board;
            const double y = (j + 0.5) * px_to_board;
            const bool on_surface = x > geo.frame_px && y > geo.frame_px &&
                                    x < geo.board_size_px - geo.frame_px &&
                                    y < geo.board_size_px - geo.frame_px;
            image.setPixel(i, j, on_surface ? surface_colour(x, y) : frame_colour(geo, x, y));
        }
    }
}

const sf::Color kInk{48, 28, 16};
const sf::Color kRed{178, 34, 38};

void add_markings(sf::VertexArray& t, const BoardGeometry& g, const ScreenMapping& m) {
    const double lw = std::max(m.length_to_screen(1.4), 1.0);
    auto S = [&m](Vec2 p) { return m.to_screen(p); };
    auto L = [&m](double v) { return m.length_to_screen(v); };
    // Surface edge line along the cushions.
    const double lo = g.frame_px + 1.0;
    const double hi = g.board_size_px - lo;
    add_line(t, S({lo, lo}), S({hi, lo}), lw, with_alpha(kInk, 0.6));
    add_line(t, S({hi, lo}), S({hi, hi}), lw, with_alpha(kInk, 0.6));
    add_line(t, S({hi, hi}), S({lo, hi}), lw, with_alpha(kInk, 0.6));
    add_line(t, S({lo, hi}), S({lo, lo}), lw, with_alpha(kInk, 0.6));
    for (const BaselineMarking& b : g.baselines) {
        for (double side : {-1.0, 1.0}) {
            const Vec2 off = b.normal * (side * b.half_gap_px);
            add_line(t, S(b.start_px + off), S(b.end_px + off), lw, kInk);
        }
        for (Vec2 c : {b.start_px, b.end_px}) {
            add_disc(t, S(c), L(b.end_circle_r_px), kRed);
            add_arc(t, S(c), L(b.end_circle_r_px), lw, 0.0, 2.0 * kPi, kInk);
        }
    }
    for (const ArrowMarking& a : g.arrows) {
        const Vec2 d = a.tip_px - a.tail_px;
        const Vec2 dir = d * (1.0 / length(d));
        const Vec2 n{-dir.y, dir.x};
        add_line(t, S(a.tail_px), S(a.tip_px - dir * a.head_px), lw, kInk);
        add_triangle(t, S(a.tip_px), S(a.tip_px - dir * (2.0 * a.head_px) + n * a.head_px),
                     S(a.tip_px - dir * (2.0 * a.head_px) - n * a.head_px), kInk);
        // The arc at the inner end opens towards the pocket.
        const Vec2 sd = S(a.tip_px) - S(a.tail_px);
        const double facing = std::atan2(sd.y, sd.x);
        add_arc(t, S(a.tail_px - dir * a.arc_r_px * 0.2), L(a.arc_r_px), lw, facing + 0.25 * kPi,
                facing + 1.75 * kPi, kInk, 48);
    }
    // Centre: outer double circle, a red rose, the small circle the queen sits on.
    add_arc(t, S(g.centre), L(g.outer_circle_r_px), lw, 0.0, 2.0 * kPi, kInk, 96);
    add_arc(t, S(g.centre), L(g.outer_circle_r_px - 4.0), lw * 0.7, 0.0, 2.0 * kPi, kInk, 96);
    for (int i = 0; i < 8; ++i) {
        const double a = kPi / 4.0 * i + kPi / 8.0;
        const Vec2 u{std::cos(a), std::sin(a)};
        const Vec2 v{-u.y, u.x};
        const Vec2 base = g.centre + u * (g.centre_circle_r_px + 2.0);
        const Vec2 tip = g.centre + u * (g.outer_circle_r_px - 8.0);
        add_triangle(t, S(base + v * 6.0), S(tip), S(base - v * 6.0), with_alpha(kRed, 0.85));
    }
    add_disc(t, S(g.centre), L(g.centre_circle_r_px), kRed);
    add_arc(t, S(g.centre), L(g.centre_circle_r_px), lw, 0.0, 2.0 * kPi, kInk);
}

void add_pockets(sf::VertexArray& t, const BoardGeometry& g, const ScreenMapping& m) {
    for (Vec2 p : g.pockets) {
        const Vec2 c = m.to_screen(p);
        const double r = m.length_to_screen(g.pocket_r_px);
        add_disc(t, c, r + m.length_to_screen(2.0), sf::Color{70, 38, 18});
        constexpr int kRings = 6;
        for (int i = 0; i < kRings; ++i) {
            const double k = 1.0 - static_cast<double>(i) / kRings;
            const auto v = static_cast<sf::Uint8>(12 + 26 * k);
            add_disc(
                t, c, r * (1.0 - 0.12 * i),
                sf::Color{v, static_cast<sf::Uint8>(v * 0.8), static_cast<sf::Uint8>(v * 0.6)});
        }
    }
}

// A piece as triangles, centred at c with radius r (window px): shadow, rim, face, ring, highlight.
void add_piece_shape(sf::VertexArray& t, Vec2 c, double r, BodyKind kind, const PieceLook& look) {
    const int seg = r > 20.0 ? 48 : 32;
    add_disc(t, c + Vec2{r * 0.12, r * 0.18}, r * 1.02, sf::Color(0, 0, 0, 70), seg);
    add_disc(t, c, r, look.rim, seg);
    add_disc(t, c, r * 0.88, look.fill, seg);
    const double ring_w = kind == BodyKind::Striker ? r * 0.12 : r * 0.06;
    add_arc(t, c, r * 0.62, ring_w, 0.0, 2.0 * kPi, look.ring, seg);
    if (kind == BodyKind::Striker) {
        add_arc(t, c, r * 0.3, r * 0.08, 0.0, 2.0 * kPi, kRed, seg);
    }
    // A soft highlight on the upper left.
    add_arc(t, c, r * 0.78, r * 0.08, 1.1 * kPi, 1.45 * kPi, sf::Color(255, 255, 255, 60), 8);
}

constexpr int kKinds = 4; // BodyKind: Black, White, Queen, Striker

} // namespace

PieceLook piece_look(BodyKind kind) {
    switch (kind) {
    case BodyKind::Black:
        return {{34, 32, 34}, {78, 74, 78}, {58, 55, 58}};
    case BodyKind::White:
        return {{240, 228, 200}, {196, 178, 146}, {214, 198, 168}};
    case BodyKind::Queen:
        return {{196, 28, 44}, {128, 16, 28}, {160, 22, 36}};
    case BodyKind::Striker:
        return {{246, 243, 234}, {160, 150, 136}, {36, 88, 168}};
    }
    return {{128, 128, 128}, {64, 64, 64}, {96, 96, 96}};
}

bool BoardPainter::repaint_band(sf::RenderTarget& target, Blitter& blitter,
                                const ScreenMapping& mapping, const Rect& band) {
    const auto w = static_cast<unsigned>(std::lround(band.w));
    const auto h = static_cast<unsigned>(std::lround(band.h));
    const auto side =
        static_cast<unsigned>(std::lround(mapping.length_to_screen(geometry_.board_size_px)));
    if (w == 0 || h == 0 || side == 0) {
        return false;
    }
    sf::RenderTexture canvas;
    sf::ContextSettings settings;
    settings.antialiasingLevel = 4;
    if (!canvas.create(w, h, settings)) {
        return false;
    }
    sf::Image wood;
    wood.create(side, side);
    paint_wood(wood, geometry_, side);
    sf::Texture wood_texture;
    wood_texture.loadFromImage(wood);
    canvas.clear(kMargin);
    // Board px -> band px; the markings are symmetric under a quarter turn, so a turned view
    // uses the same picture.
    const Rect board{std::round(mapping.origin_x) - band.x, std::round(mapping.origin_y) - band.y,
                     static_cast<double>(side), static_cast<double>(side)};
    sf::Sprite sprite(wood_texture);
    sprite.setPosition(f(board.x), f(board.y));
    canvas.draw(sprite);
    const ScreenMapping local = make_mapping(board, geometry_.board_size_px);
    sf::VertexArray tris(sf::Triangles);
    add_markings(tris, geometry_, local);
    add_pockets(tris, geometry_, local);
    canvas.draw(tris);
    canvas.display();
    ++repaints_;
    return blitter.upload(target, band_, canvas.getTexture().copyToImage());
}

bool BoardPainter::repaint_atlas(sf::RenderTarget& target, Blitter& blitter, double scale) {
    const double striker_r = geometry_.striker_r_px * scale;
    cell_px_ = 2.0 * std::ceil(striker_r * 1.25 + 2.0);
    const auto cell = static_cast<unsigned>(cell_px_);
    sf::RenderTexture canvas;
    sf::ContextSettings settings;
    settings.antialiasingLevel = 4;
    if (!canvas.create(cell * kKinds, cell, settings)) {
        return false;
    }
    // Drawn with the usual alpha blend over transparent black: opaque parts and the black
    // shadow come out the same premultiplied or not, antialiased edges come out premultiplied.
    canvas.clear(sf::Color::Transparent);
    sf::VertexArray tris(sf::Triangles);
    for (int k = 0; k < kKinds; ++k) {
        const auto kind = static_cast<BodyKind>(k);
        const double r =
            (kind == BodyKind::Striker ? geometry_.striker_r_px : geometry_.coin_r_px) * scale;
        add_piece_shape(tris, {cell_px_ * (k + 0.5), cell_px_ * 0.5}, r, kind, piece_look(kind));
    }
    canvas.draw(tris);
    canvas.display();
    ++repaints_;
    return blitter.upload(target, atlas_, canvas.getTexture().copyToImage());
}

void BoardPainter::draw_board(sf::RenderTarget& target, Blitter& blitter,
                              const ScreenMapping& mapping, const Rect& band) {
    const Vec2 origin{mapping.origin_x, mapping.origin_y};
    if (!band_ok_ || band != painted_band_ || !(origin == painted_origin_) ||
        mapping.scale != painted_scale_) {
        band_ok_ = repaint_band(target, blitter, mapping, band);
        painted_band_ = band;
        painted_origin_ = origin;
        painted_scale_ = mapping.scale;
    }
    if (band_ok_) {
        blitter.copy(target, band_, f(band.x), f(band.y));
    } else {
        draw_panel(target, band, kMargin);
    }
}

void BoardPainter::draw_pieces(sf::RenderTarget& target, Blitter& blitter,
                               const ScreenMapping& mapping,
                               const std::vector<RenderedBody>& bodies) {
    if (atlas_scale_ != mapping.scale) {
        atlas_ok_ = repaint_atlas(target, blitter, mapping.scale);
        atlas_scale_ = mapping.scale;
    }
    if (!atlas_ok_) {
        return;
    }
    resting_.clear();
    falling_.clear();
    for (const RenderedBody& b : bodies) {
        const Vec2 c = mapping.to_screen(b.pos_px);
        const Rect cell{cell_px_ * static_cast<int>(b.kind), 0.0, cell_px_, cell_px_};
        if (b.scale == 1.0 && b.alpha >= 1.0) {
            // Whole px, so the texels land 1:1 (nearest sampling).
            const Rect dst{std::round(c.x - cell_px_ / 2.0), std::round(c.y - cell_px_ / 2.0),
                           cell_px_, cell_px_};
            Blitter::add_rect(resting_, dst, cell);
            continue;
        }
        // Fading: all four channels scaled, as the colours are premultiplied.
        const double half = cell_px_ * 0.5 * b.scale;
        const auto a = static_cast<sf::Uint8>(std::lround(std::clamp(b.alpha, 0.0, 1.0) * 255.0));
        Blitter::add_rect(falling_, {c.x - half, c.y - half, 2.0 * half, 2.0 * half}, cell,
                          sf::Color(a, a, a, a));
    }
    if (falling_.getVertexCount() > 0) {
        target.draw(falling_, sf::RenderStates(Blitter::kPremultiplied, sf::Transform::Identity,
                                               &atlas_, nullptr));
    }
    if (resting_.getVertexCount() > 0) {
        blitter.draw_premultiplied(target, resting_, atlas_);
    }
}

void BoardPainter::draw_striker(sf::RenderTarget& target, Blitter& blitter,
                                const ScreenMapping& mapping, Vec2 pos_px, double alpha,
                                bool warning, std::optional<std::pair<Vec2, double>> blocking) {
    draw_pieces(
        target, blitter, mapping,
        {RenderedBody{0, BodyKind::Striker, pos_px, 1.0, warning ? kOverlapAlpha : alpha, false}});
    if (warning) {
        overlay_.clear();
        const double r = mapping.length_to_screen(geometry_.striker_r_px);
        add_arc(overlay_, mapping.to_screen(pos_px), r + 2.0, 3.0, 0.0, 2.0 * kPi,
                sf::Color(230, 20, 20), 48);
        if (blocking) {
            add_arc(overlay_, mapping.to_screen(blocking->first),
                    mapping.length_to_screen(blocking->second) + 2.0, 2.5, 0.0, 2.0 * kPi,
                    sf::Color(255, 230, 60), 40);
        }
        target.draw(overlay_);
    }
}

} // namespace carrom::client::app
