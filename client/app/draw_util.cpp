#include "draw_util.hpp"

#include <cmath>
#include <numbers>

namespace carrom::client::app {

void add_triangle(sf::VertexArray& tris, Vec2 a, Vec2 b, Vec2 c, sf::Color colour) {
    tris.append({to_sf(a), colour});
    tris.append({to_sf(b), colour});
    tris.append({to_sf(c), colour});
}

void add_line(sf::VertexArray& tris, Vec2 a, Vec2 b, double w, sf::Color colour) {
    const Vec2 d = b - a;
    const double len = length(d);
    if (len <= 0.0) {
        return;
    }
    const Vec2 n = Vec2{-d.y, d.x} * (0.5 * w / len);
    add_triangle(tris, a + n, b + n, b - n, colour);
    add_triangle(tris, a + n, b - n, a - n, colour);
}

void add_arc(sf::VertexArray& tris, Vec2 centre, double r, double w, double a0, double a1,
             sf::Color colour, int segments) {
    const double inner = std::max(r - w / 2.0, 0.0);
    const double outer = r + w / 2.0;
    for (int i = 0; i < segments; ++i) {
        const double t0 = a0 + (a1 - a0) * static_cast<double>(i) / segments;
        const double t1 = a0 + (a1 - a0) * static_cast<double>(i + 1) / segments;
        const Vec2 u0{std::cos(t0), std::sin(t0)};
        const Vec2 u1{std::cos(t1), std::sin(t1)};
        add_triangle(tris, centre + u0 * inner, centre + u0 * outer, centre + u1 * outer, colour);
        add_triangle(tris, centre + u0 * inner, centre + u1 * outer, centre + u1 * inner, colour);
    }
}

void add_disc(sf::VertexArray& tris, Vec2 centre, double r, sf::Color colour, int segments) {
    for (int i = 0; i < segments; ++i) {
        const double t0 = 2.0 * std::numbers::pi * i / segments;
        const double t1 = 2.0 * std::numbers::pi * (i + 1) / segments;
        add_triangle(tris, centre, centre + Vec2{std::cos(t0), std::sin(t0)} * r,
                     centre + Vec2{std::cos(t1), std::sin(t1)} * r, colour);
    }
}

} // namespace carrom::client::app
