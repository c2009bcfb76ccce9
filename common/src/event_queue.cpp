// Event prediction and the event queue. A body's prediction (next[i]) is its earliest event:
// its stop, a cushion, a pocket, or a contact with a body whose path box overlaps its own. The
// queue is the array of keys (keys[i] == next[i].key: u = e^(-k t), or -S with travel_keys); the
// next event is the largest key, ties to the lower index (earliest, advance: event_queue.hpp).

#include "broad_phase.hpp"
#include "contact_time.hpp"
#include "engine_state.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace carrom {

using detail::Box;
using detail::kNever;
using detail::kNoEvent;
using detail::Next;
using detail::Prediction;

// Recomputes next[i] from the current state. Needs body i's path box current (refresh); with
// use_near, brings row i of near[] up to date first.
void ExactEngine::Impl::predict(std::size_t i) {
    Prediction best;
    double best_s = kNever;
    if (!active[i]) {
        set_next(i, best);
        return;
    }
    if (moving[i]) {
        best_s = stop_s(i);
        best.kind = Next::Stop;
        bool high = false;
        double s = detail::time_to_wall(pos[i].x, vel[i].x, lo[i], hi[i], best_s, high);
        if (s < best_s) {
            best_s = s;
            best = {0.0, Next::Cushion, high ? kCushionRight : kCushionLeft};
        }
        s = detail::time_to_wall(pos[i].y, vel[i].y, lo[i], hi[i], best_s, high);
        if (s < best_s) {
            best_s = s;
            best = {0.0, Next::Cushion, high ? kCushionBottom : kCushionTop};
        }
        const bool between_pockets = (sweep_x0[i] > pocket_gap.x0 && sweep_x1[i] < pocket_gap.x1) ||
                                     (sweep_y0[i] > pocket_gap.y0 && sweep_y1[i] < pocket_gap.y1);
        for (std::size_t p = 0; !between_pockets && p < pockets.size(); ++p) {
            const Box& pb = pocket_boxes[p];
            if (!(sweep_x0[i] <= pb.x1 && pb.x0 <= sweep_x1[i] && sweep_y0[i] <= pb.y1 &&
                  pb.y0 <= sweep_y1[i])) {
                continue;
            }
            s = detail::time_to_reach(pockets[p] - pos[i], -vel[i], config.pocket_radius_px,
                                      best_s);
            if (s < best_s) {
                best_s = s;
                best = {0.0, Next::Pocket, static_cast<int>(p)};
            }
        }
    }
    // Broad phase: only bodies whose path boxes overlap body i's.
    const std::size_t n = pos.size();
    if (use_near) {
        if (box_dirty[i]) {
            update_near(i);
        }
        // Only active partners, and only moving ones if i is at rest (two bodies at rest never
        // meet). Raw pointers: the loop stores nothing, so nothing is reloaded.
        const std::uint64_t candidates =
            near[i] & active_mask & (moving[i] ? ~std::uint64_t{0} : moving_mask);
        const Vec2* const p = pos.data();
        const Vec2* const v = vel.data();
        const double* const r = radius.data();
        const Vec2 pi = p[i];
        const Vec2 vi = v[i];
        const double ri = r[i];
        int tests = 0;
        for (std::uint64_t row = candidates; row != 0; row &= row - 1) {
            const auto j = static_cast<std::size_t>(std::countr_zero(row));
            ++tests;
            const double s = detail::time_to_reach(p[j] - pi, v[j] - vi, ri + r[j], best_s);
            // The contact counts only if it comes before body j stops.
            if (s < best_s && (!moving[j] || s < stop_s(j))) {
                best_s = s;
                best = {0.0, Next::Pair, static_cast<int>(j)};
            }
        }
        result.stats.pair_tests += tests;
    } else {
        for (std::size_t j = 0; j < n; ++j) {
            if (!(sweep_x0[i] <= sweep_x1[j] && sweep_x0[j] <= sweep_x1[i] &&
                  sweep_y0[i] <= sweep_y1[j] && sweep_y0[j] <= sweep_y1[i])) {
                continue;
            }
            if (j == i || !active[j] || (!moving[i] && !moving[j])) {
                continue;
            }
            ++result.stats.pair_tests;
            const double s = detail::time_to_reach(pos[j] - pos[i], vel[j] - vel[i],
                                                   radius[i] + radius[j], best_s);
            // The contact counts only if it comes before body j stops.
            if (s < best_s && (!moving[j] || s < stop_s(j))) {
                best_s = s;
                best = {0.0, Next::Pair, static_cast<int>(j)};
            }
        }
    }
    if (best_s == kNever) {
        best.kind = Next::None; // no stop either (k = 0): nothing ever happens to body i
    }
    best.key = best.kind == Next::None ? kNoEvent : key_after(best_s);
    set_next(i, best);
}

void ExactEngine::Impl::set_next(std::size_t i, const Prediction& p) {
    if (use_near) {
        const std::uint64_t bit = std::uint64_t{1} << i;
        if (next[i].kind == Next::Pair) {
            watchers[static_cast<std::size_t>(next[i].other)] &= ~bit;
        }
        if (p.kind == Next::Pair) {
            watchers[static_cast<std::size_t>(p.other)] |= bit;
        }
    }
    next[i] = p;
    keys[i] = p.key;
}

} // namespace carrom
