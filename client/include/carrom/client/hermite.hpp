#pragma once
// Cubic Hermite interpolation of a position from its end points and end velocities.

#include "carrom/vec2.hpp"

namespace carrom::client {

// Position at fraction s in [0, 1] of an interval of dt_s seconds that starts at p0 with velocity
// v0 and ends at p1 with velocity v1 (px, px/s). s = 0 gives p0, s = 1 gives p1, and the curve's
// derivative at the ends is v0 and v1.
inline Vec2 hermite(Vec2 p0, Vec2 v0, Vec2 p1, Vec2 v1, double dt_s, double s) {
    const double s2 = s * s;
    const double s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    const double h10 = s3 - 2.0 * s2 + s;
    const double h01 = -2.0 * s3 + 3.0 * s2;
    const double h11 = s3 - s2;
    return p0 * h00 + v0 * (h10 * dt_s) + p1 * h01 + v1 * (h11 * dt_s);
}

} // namespace carrom::client
