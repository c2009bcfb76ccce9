#pragma once
// Closed-form times of contact. All bodies share one damping rate k, so between events every
// moving body's path is linear in the travel factor s = (1 - e^(-k t)) / k, s, measured from the
// current time: p(s) = p + v s. Contact conditions are therefore roots of quadratics in s.

#include "carrom/vec2.hpp"

#include <cmath>
#include <limits>

namespace carrom::detail {

inline constexpr double kNever = std::numeric_limits<double>::infinity();
// Two surfaces closer than this are touching, px.
inline constexpr double kTouchTolerancePx = 1e-9;
// A touching pair approaching slower than this is not an impact, px/s. Its possible overlap is
// bounded by this speed times 1/k (about 1.1e-8 px).
inline constexpr double kApproachTolerancePxS = 1e-8;

// Earliest s in [0, s_max] at which a point moving from relative position d with relative
// velocity w (both of "b" relative to "a") reaches distance reach while approaching; kNever if
// it does not. Touching (within kTouchTolerancePx) and approaching gives 0. Uses the root form
// s = c / (-b + sqrt(b^2 - a c)), free of cancellation for near-touching and grazing contacts.
inline double time_to_reach(Vec2 d, Vec2 w, double reach, double s_max) {
    const double b = dot(d, w);
    if (b >= 0.0) {
        return kNever; // not approaching
    }
    const double dd = dot(d, d);
    const double touch = reach + kTouchTolerancePx;
    if (dd <= touch * touch) {
        return -b > kApproachTolerancePxS * std::sqrt(dd) ? 0.0 : kNever;
    }
    // c = |d|^2 - reach^2. Far apart, the direct difference loses nothing; near touching it is
    // computed as (|d| - reach)(|d| + reach) to keep the small gap exact.
    // With c > 0, sqrt(b^2 - a c) <= -b, so the root is at least c / (-2 b): when c exceeds
    // `late`, the root is beyond s_max even after rounding, the same answer as the full solve.
    const double late = 2.000001 * -b * s_max;
    const double rr = reach * reach;
    const double a = dot(w, w);
    double c = dd - rr;
    if (dd < 4.0 * rr) {
        // The direct c differs from the near-touching form by less than 1e-15 (rr + |c|) (both
        // are within a few roundings of the true value; docs/physics.md, "Speed"), so a
        // margin of 1e-13 of the magnitudes decides these two rejections without the square
        // roots, exactly as the full solve below would.
        const double slack = 1e-13 * (rr + std::fabs(c));
        if (c - slack > late || b * b - a * c + 1e-13 * (b * b + a * (rr + std::fabs(c))) < 0.0) {
            return kNever;
        }
        const double dist = std::sqrt(dd);
        c = (dist - reach) * (dist + reach);
    }
    if (c > late) {
        return kNever;
    }
    const double disc = b * b - a * c;
    if (disc < 0.0) {
        return kNever;
    }
    const double s = c / (-b + std::sqrt(disc));
    return s <= s_max ? s : kNever;
}

// Earliest s in [0, s_max] at which coordinate x moving at vx reaches the wall at `lo` (moving
// down) or `hi` (moving up). Sets `high_side` to say which.
inline double time_to_wall(double x, double vx, double lo, double hi, double s_max,
                           bool& high_side) {
    double s = kNever;
    if (vx < -kApproachTolerancePxS) {
        s = x - lo <= kTouchTolerancePx ? 0.0 : (lo - x) / vx;
        high_side = false;
    } else if (vx > kApproachTolerancePxS) {
        s = hi - x <= kTouchTolerancePx ? 0.0 : (hi - x) / vx;
        high_side = true;
    }
    return s <= s_max ? s : kNever;
}

} // namespace carrom::detail
