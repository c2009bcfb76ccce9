#pragma once
// Plain 2D vector of doubles. Board coordinates: px, origin at the board's top-left corner,
// x to the right, y downwards (as on screen).

#include <cmath>

namespace carrom {

struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
    friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
    friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
    friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
    friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
    constexpr Vec2& operator+=(Vec2 b) {
        x += b.x;
        y += b.y;
        return *this;
    }
    constexpr Vec2& operator-=(Vec2 b) {
        x -= b.x;
        y -= b.y;
        return *this;
    }
    constexpr Vec2& operator*=(double s) {
        x *= s;
        y *= s;
        return *this;
    }
    friend constexpr bool operator==(Vec2 a, Vec2 b) = default;
};

constexpr double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
constexpr double cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
constexpr double length_squared(Vec2 a) {
    return dot(a, a);
}
inline double length(Vec2 a) {
    return std::sqrt(dot(a, a));
}
inline bool is_finite(Vec2 a) {
    return std::isfinite(a.x) && std::isfinite(a.y);
}

} // namespace carrom
