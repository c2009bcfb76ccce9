#pragma once
// Small drawing helpers on top of SFML: thick lines, rings and arcs as triangles, and conversion
// from the board's doubles to SFML's floats.

#include "carrom/vec2.hpp"

#include <SFML/Graphics.hpp>

#include <algorithm>
#include <cmath>

namespace carrom::client::app {

inline sf::Vector2f to_sf(Vec2 v) {
    return {static_cast<float>(v.x), static_cast<float>(v.y)};
}
inline float f(double v) {
    return static_cast<float>(v);
}
// A size in window px (a font size, a margin): `fraction` of `length`, clamped to [lo, hi] and
// rounded.
inline unsigned scaled_size(double length, double fraction, double lo, double hi) {
    return static_cast<unsigned>(std::lround(std::clamp(length * fraction, lo, hi)));
}
inline sf::Color with_alpha(sf::Color c, double alpha) {
    c.a = static_cast<sf::Uint8>(std::clamp(alpha, 0.0, 1.0) * c.a);
    return c;
}

// Appends a line segment of width w (window px) to a Triangles array.
void add_line(sf::VertexArray& tris, Vec2 a, Vec2 b, double w, sf::Color colour);
// Appends a ring (annulus between r - w/2 and r + w/2) or an arc of it, from angle a0 to a1 (rad).
void add_arc(sf::VertexArray& tris, Vec2 centre, double r, double w, double a0, double a1,
             sf::Color colour, int segments = 64);
// Appends a filled disc.
void add_disc(sf::VertexArray& tris, Vec2 centre, double r, sf::Color colour, int segments = 48);
// Appends a filled triangle.
void add_triangle(sf::VertexArray& tris, Vec2 a, Vec2 b, Vec2 c, sf::Color colour);

} // namespace carrom::client::app
