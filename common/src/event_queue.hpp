#pragma once
// The event queue's two per-event steps, inline because run_events calls them for every event:
// earliest (which body's prediction comes first) and advance (every body to that time). The
// queue is the array of keys, keys[i] == next[i].key (u = e^(-k t), or -S with travel_keys;
// engine_state.hpp); predict fills it (event_queue.cpp).

#include "carrom/det_math.hpp"
#include "engine_state.hpp"

#include <algorithm>
#include <cstddef>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace carrom {

// The body whose event comes first: the largest key, ties to the lower index. keys[] is padded
// to an even length with kNoEvent.
inline std::size_t ExactEngine::Impl::earliest() const {
    std::size_t first = 0;
    const double* const kp = keys.data();
    const std::size_t count = keys.size();
#if defined(__SSE2__)
    __m128d top = _mm_loadu_pd(kp);
    for (std::size_t i = 2; i < count; i += 2) {
        top = _mm_max_pd(top, _mm_loadu_pd(kp + i));
    }
    const double first_key = std::max(_mm_cvtsd_f64(top), _mm_cvtsd_f64(_mm_unpackhi_pd(top, top)));
    while (kp[first] != first_key) {
        ++first;
    }
#else
    double first_key = kp[0];
    for (std::size_t i = 1; i < count; ++i) {
        const bool later = kp[i] > first_key;
        first = later ? i : first;
        first_key = later ? kp[i] : first_key;
    }
#endif
    return first;
}

// Moves every body to the time whose key is `key` (a time not before now).
inline void ExactEngine::Impl::advance(double key) {
    double decay = 0.0; // e^(-k dt)
    double s = 0.0;     // (1 - e^(-k dt)) / k, s
    if (!travel_keys) {
        if (key >= u_now) {
            return;
        }
        decay = key / u_now;
        s = (1.0 - decay) * inv_k;
    } else {
        // key = -(S(now + dt) - S(now)) = -e^(-k now) (1 - e^(-k dt)) / k = -u_now s.
        if (key >= 0.0) {
            return;
        }
        s = -key / u_now;
        decay = 1.0 - k * s;
    }
    // Raw pointers: the stores cannot alias the vectors themselves, so nothing is reloaded.
    Vec2* const p = pos.data();
    Vec2* const v = vel.data();
    double* const sp = speed.data();
    const auto move = [p, v, sp, s, decay](std::size_t i) {
        const Vec2 vi = v[i];
        p[i] += vi * s;
        v[i] = vi * decay;
        sp[i] *= decay;
    };
    const std::size_t n = pos.size();
    if (use_near) {
        // At most 64 bodies: one branch-free pass over all of them (vectorised), cheaper than
        // walking moving_mask. A body at rest or pocketed has v == 0 and speed 0, so
        // p + 0 * s == p and its state is unchanged.
        for (std::size_t i = 0; i < n; ++i) {
            move(i);
        }
    } else {
        if (moving_list_stale) {
            moving_list.clear();
            for (std::size_t i = 0; i < n; ++i) {
                if (moving[i]) {
                    moving_list.push_back(static_cast<int>(i));
                }
            }
            moving_list_stale = false;
        }
        for (int mi : moving_list) {
            move(static_cast<std::size_t>(mi));
        }
    }
    if (!travel_keys) {
        u_now = key;
        now_stale = true;
        return;
    }
    u_now *= decay;
    // dt = -ln(1 - k s) / k = s (-ln(1 - x) / x), x = k s, which is 1 at x = 0 (and for a
    // subnormal x, where log1p(-x) == -x).
    const double x = k * s;
    now += x == 0.0 ? s : s * (-det::log1p(-x) / x);
    // Keys are measured from now: every one moves up by the travel just made (-key). A key
    // of kNoEvent stays -infinity.
    double* const kp = keys.data();
    for (std::size_t i = 0; i < keys.size(); ++i) {
        kp[i] -= key;
    }
    for (detail::Prediction& prediction : next) {
        prediction.key -= key;
    }
}

} // namespace carrom
