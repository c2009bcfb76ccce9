#pragma once
// The broad phase (use_near, at most 64 bodies): which pairs of bodies can meet, from path
// boxes, and which touch at the current instant. Inline, because predict, process_instant and
// run_events call these for every event.
//
// A body's path box covers the rest of its current path, radius included (px): from its
// position to where it stops, or its position alone at rest. near[] is the overlap relation of
// the float boxes; two bodies can touch only if their near bit is set. touch_mask narrows it to
// the pairs that touch now (gap <= kTouchTolerancePx).

#include "contact_time.hpp"
#include "engine_state.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace carrom {

namespace detail {

// A float below (above) the finite x, px: x is moved outwards by 1e-3 px plus 1e-6 of |x|, more
// than the relative rounding of the conversion (2^-24), so the float box contains the double
// box. Branch-free, unlike std::nextafter.
inline float float_down(double x) {
    return static_cast<float>(x - (std::fabs(x) * 1e-6 + 1e-3));
}
inline float float_up(double x) {
    return static_cast<float>(x + (std::fabs(x) * 1e-6 + 1e-3));
}

} // namespace detail

// Body i's velocity or activity changed: updates its speed, its moving and active bits and its
// path box, and marks its near[] row dirty.
inline void ExactEngine::Impl::refresh(std::size_t i) {
    const Vec2 p = pos[i];
    const Vec2 v = vel[i];
    const double sp = length(v);
    speed[i] = sp;
    const bool is_active = active[i] != 0;
    const bool now_moving = is_active && sp > 0.0;
    if (use_near) {
        // Branch-free: bit i of each mask is replaced.
        const std::uint64_t bit = std::uint64_t{1} << i;
        active_mask = (active_mask & ~bit) | (static_cast<std::uint64_t>(is_active) << i);
        moving_mask = (moving_mask & ~bit) | (static_cast<std::uint64_t>(now_moving) << i);
    } else {
        moving_list_stale = moving_list_stale || now_moving != (moving[i] != 0);
    }
    moving[i] = static_cast<char>(now_moving);
    box_dirty[i] = 1;
    const double r = radius[i];
    Vec2 end = p;
    if (now_moving && !travel_keys) {
        end += v * ((1.0 - config.stop_speed_px_s / sp) * inv_k); // the stop, stop_s(i)
    } else if (now_moving) {
        // The stop may be far away or never come (k = 0): the box ends where the path leaves
        // the cushion range, which it cannot before its next event.
        end +=
            v * std::min((1.0 - config.stop_speed_px_s / sp) * inv_k, detail::kLongestBoxTravelS);
        end = {std::clamp(end.x, lo[i], hi[i]), std::clamp(end.y, lo[i], hi[i])};
    }
    const double x0 = std::min(p.x, end.x) - r;
    const double y0 = std::min(p.y, end.y) - r;
    const double x1 = std::max(p.x, end.x) + r;
    const double y1 = std::max(p.y, end.y) + r;
    sweep_x0[i] = x0;
    sweep_y0[i] = y0;
    sweep_x1[i] = x1;
    sweep_y1[i] = y1;
    box_x0[i] = detail::float_down(x0);
    box_y0[i] = detail::float_down(y0);
    box_x1[i] = detail::float_up(x1);
    box_y1[i] = detail::float_up(y1);
}

// Recomputes row i of near[] from the current boxes and keeps near symmetric by flipping bit i
// of every body whose bit in row i changed. Only for active bodies (a pocketed body's row is
// kept up to date by the flips of the others).
inline void ExactEngine::Impl::update_near(std::size_t i) {
    const std::uint64_t row = box_overlaps(i) & ~(std::uint64_t{1} << i);
    for (std::uint64_t diff = row ^ near[i]; diff != 0; diff &= diff - 1) {
        near[static_cast<std::size_t>(std::countr_zero(diff))] ^= std::uint64_t{1} << i;
    }
    near[i] = row;
    box_dirty[i] = 0;
}

// Bit j set: the float path boxes of i and j overlap (i itself included). n <= 64. The float
// boxes contain the double ones, so every pair whose double boxes overlap is included (and a
// few more that merely pass the float test; their contact solve simply finds no contact).
inline std::uint64_t ExactEngine::Impl::box_overlaps(std::size_t i) const {
    const float* bx0 = box_x0.data();
    const float* by0 = box_y0.data();
    const float* bx1 = box_x1.data();
    const float* by1 = box_y1.data();
    std::uint64_t row = 0;
    const std::size_t n = box_x0.size();
#if defined(__SSE2__)
    const __m128 x0 = _mm_set1_ps(bx0[i]);
    const __m128 y0 = _mm_set1_ps(by0[i]);
    const __m128 x1 = _mm_set1_ps(bx1[i]);
    const __m128 y1 = _mm_set1_ps(by1[i]);
    for (std::size_t j = 0; j < n; j += 4) {
        const __m128 hit_x = _mm_and_ps(_mm_cmple_ps(x0, _mm_loadu_ps(bx1 + j)),
                                        _mm_cmple_ps(_mm_loadu_ps(bx0 + j), x1));
        const __m128 hit_y = _mm_and_ps(_mm_cmple_ps(y0, _mm_loadu_ps(by1 + j)),
                                        _mm_cmple_ps(_mm_loadu_ps(by0 + j), y1));
        const auto bits = static_cast<std::uint64_t>(_mm_movemask_ps(_mm_and_ps(hit_x, hit_y)));
        row |= bits << j;
    }
#else
    const float x0 = bx0[i], y0 = by0[i], x1 = bx1[i], y1 = by1[i];
    for (std::size_t j = 0; j < n; ++j) {
        const bool hit = (x0 <= bx1[j]) & (bx0[j] <= x1) & (y0 <= by1[j]) & (by0[j] <= y1);
        row |= static_cast<std::uint64_t>(hit) << j;
    }
#endif
    return row;
}

// Bit b set: bodies a and b touch (gap <= kTouchTolerancePx) and their path boxes overlap
// (near[a] bit b). Positions and near[] do not change during an instant, so process_instant
// computes each body's mask at most once per instant (touch_stamp == instant_stamp).
inline std::uint64_t ExactEngine::Impl::touch_mask(std::size_t a) {
    if (touch_stamp[a] == instant_stamp) {
        return touch_bits[a];
    }
    const Vec2 pa = pos[a];
    const double ra = radius[a];
    std::uint64_t mask = 0;
    for (std::uint64_t bits = near[a]; bits != 0; bits &= bits - 1) {
        const auto b = static_cast<std::size_t>(std::countr_zero(bits));
        const Vec2 d = pos[b] - pa;
        const double touch = ra + radius[b] + detail::kTouchTolerancePx;
        const bool touching = length_squared(d) <= touch * touch;
        mask |= static_cast<std::uint64_t>(touching) << b;
    }
    const Vec2 lo_gap = pa - Vec2{lo[a], lo[a]};
    const Vec2 hi_gap = Vec2{hi[a], hi[a]} - pa;
    wall_bits[a] = static_cast<std::uint8_t>((lo_gap.x <= detail::kTouchTolerancePx ? 1 : 0) |
                                             (hi_gap.x <= detail::kTouchTolerancePx ? 2 : 0) |
                                             (lo_gap.y <= detail::kTouchTolerancePx ? 4 : 0) |
                                             (hi_gap.y <= detail::kTouchTolerancePx ? 8 : 0));
    touch_stamp[a] = instant_stamp;
    touch_bits[a] = mask;
    return mask;
}

} // namespace carrom
