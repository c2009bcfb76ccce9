// The run: the engine's set-up for a scene (load, settle_initial_state, the resting-layout
// cache), the event loop (run_events) and the final state (finish).

#include "broad_phase.hpp"
#include "carrom/det_math.hpp"
#include "contact_time.hpp"
#include "engine_state.hpp"
#include "event_queue.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace carrom {

using detail::Box;
using detail::kFarAway;
using detail::kNever;
using detail::kNoEvent;
using detail::Next;
using detail::Prediction;

ExactEngine::Impl::Impl(const PhysicsConfig& c) : config(c) {
    k = c.damping_per_s;
    inv_k = 1.0 / k;
    travel_keys = k < detail::kTravelKeyDampingPerS;
    pockets = c.pocket_centres();
    for (std::size_t p = 0; p < pockets.size(); ++p) {
        const double r = c.pocket_radius_px;
        pocket_boxes[p] = {pockets[p].x - r, pockets[p].y - r, pockets[p].x + r, pockets[p].y + r};
    }
    const double mid = 0.5 * c.board_size_px;
    pocket_gap = {-kNever, -kNever, kNever, kNever};
    for (const Box& pb : pocket_boxes) {
        if (pb.x0 + pb.x1 < 2.0 * mid) {
            pocket_gap.x0 = std::max(pocket_gap.x0, pb.x1);
        } else {
            pocket_gap.x1 = std::min(pocket_gap.x1, pb.x0);
        }
        if (pb.y0 + pb.y1 < 2.0 * mid) {
            pocket_gap.y0 = std::max(pocket_gap.y0, pb.y1);
        } else {
            pocket_gap.y1 = std::min(pocket_gap.y1, pb.y0);
        }
    }
}

void ExactEngine::Impl::load(std::span<const Body> bodies) {
    const std::size_t n = bodies.size();
    ids.resize(n);
    pos.resize(n);
    vel.resize(n);
    speed.resize(n);
    radius.resize(n);
    inv_mass.resize(n);
    lo.resize(n);
    hi.resize(n);
    active.resize(n);
    moving.resize(n);
    // Padded to an even length with empty boxes (see box_overlaps).
    const std::size_t padded = n + (n % 2);
    sweep_x0.assign(padded, kNever);
    sweep_y0.assign(padded, kNever);
    sweep_x1.assign(padded, -kNever);
    sweep_y1.assign(padded, -kNever);
    const std::size_t padded4 = (n + 3) / 4 * 4;
    constexpr float kFloatNever = std::numeric_limits<float>::infinity();
    box_x0.assign(padded4, kFloatNever);
    box_y0.assign(padded4, kFloatNever);
    box_x1.assign(padded4, -kFloatNever);
    box_y1.assign(padded4, -kFloatNever);
    pocketed_at.assign(n, Vec2{});
    near.assign(n, 0);
    touch_bits.assign(n, 0);
    touch_stamp.assign(n, 0);
    wall_bits.assign(n, 0);
    instant_stamp = 0;
    moving_list_stale = true;
    use_near = n <= 64;
    next.assign(n, Prediction{});
    keys.assign(n + (n % 2), kNoEvent); // padded to an even length with kNoEvent
    watchers.assign(n, 0);
    box_dirty.assign(n, 1);
    in_frontier.assign(n, 0);
    is_touched.assign(n, 0);
    in_cluster.assign(n, 0);
    root.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Body& b = bodies[i];
        ids[i] = b.id;
        pos[i] = b.pos_px;
        active[i] = !b.pocketed;
        vel[i] = active[i] ? b.vel_px_s : Vec2{};
        speed[i] = length(vel[i]);
        radius[i] = config.radius(b.kind);
        inv_mass[i] = 1.0 / config.mass(b.kind);
        lo[i] = config.cushion_min(radius[i]);
        hi[i] = config.cushion_max(radius[i]);
        moving[i] = speed[i] > 0.0;
        if (!active[i]) {
            pocketed_at[i] = pos[i];
            pos[i] = kFarAway;
        }
    }
    solve_inv_mass = inv_mass;
    active_mask = 0;
    moving_mask = 0;
    for (std::size_t i = 0; use_near && i < n; ++i) {
        active_mask |= static_cast<std::uint64_t>(active[i] != 0) << i;
        moving_mask |= static_cast<std::uint64_t>(moving[i] != 0) << i;
    }
    max_radius = 0.0;
    for (double r : radius) {
        max_radius = std::max(max_radius, r);
    }
    now = 0.0;
    u_now = 1.0;
    now_stale = false;
    result.bodies.assign(bodies.begin(), bodies.end());
    result.events.clear();
    result.pocket_order.clear();
    result.collision_counts.assign(bodies.size(), 0);
    result.trajectory.initial.clear();
    result.trajectory.segments.clear();
    if (options.record_trajectory) {
        result.trajectory.initial.assign(bodies.begin(), bodies.end());
    }
    result.end_time_s = 0.0;
    result.truncated = false;
    result.stats = {};
}

void ExactEngine::Impl::stop_body(std::size_t i) {
    vel[i] = {};
    emit(EventKind::Stop, i, -1, 0.0);
    refresh(i);
    record_segment(i);
}

void ExactEngine::Impl::pocket_body(std::size_t i, int pocket) {
    active[i] = 0;
    vel[i] = {};
    emit(EventKind::Pocket, i, pocket, 0.0);
    result.pocket_order.push_back(ids[i]);
    record_segment(i);
    pocketed_at[i] = pos[i];
    pos[i] = kFarAway;
    refresh(i);
}

void ExactEngine::Impl::settle_initial_state(std::uint64_t unchanged) {
    // Bodies at rest now and in the previous set-up, with the same data: their boxes and
    // their rows among themselves are those of the previous run. They were active and at rest
    // then, so they are neither in a pocket nor below the stop speed now.
    const std::uint64_t reuse = use_near && cached_near.size() == pos.size()
                                    ? unchanged & resting_cached & ~moving_mask
                                    : 0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        if (i < 64 && ((reuse >> i) & 1U) != 0) {
            restore_resting_box(i);
            continue;
        }
        if (!active[i]) {
            continue;
        }
        for (std::size_t p = 0; p < pockets.size(); ++p) {
            // |d| >= max(|d.x|, |d.y|) (also after rounding): most bodies fail the cheap test.
            const Vec2 d = pos[i] - pockets[p];
            if (std::fabs(d.x) >= config.pocket_radius_px ||
                std::fabs(d.y) >= config.pocket_radius_px) {
                continue;
            }
            if (length(d) < config.pocket_radius_px) {
                pocket_body(i, static_cast<int>(p));
                break;
            }
        }
        if (active[i] && speed[i] > 0.0 && speed[i] <= config.stop_speed_px_s) {
            stop_body(i);
        }
        refresh(i);
    }
    frontier.clear();
    std::vector<int>& seeds = event_seeds;
    seeds.clear();
    for (std::size_t i = 0; i < pos.size(); ++i) {
        if (moving[i]) {
            seeds.push_back(static_cast<int>(i));
        }
    }
    if (!seeds.empty()) {
        process_instant(seeds);
        clear_touched();
    }
    // Every row of near[] must be current before any prediction reads it. The reused rows
    // first (they hold only bits among reused bodies, so near[] stays symmetric), then the
    // others, which set their bits in every row they overlap: the result is the overlap
    // relation of all boxes, as if every row had been computed.
    for (std::uint64_t bits = reuse; bits != 0; bits &= bits - 1) {
        const auto i = static_cast<std::size_t>(std::countr_zero(bits));
        near[i] = cached_near[i] & reuse;
        box_dirty[i] = 0;
    }
    for (std::size_t i = 0; use_near && i < pos.size(); ++i) {
        if (active[i] && box_dirty[i]) {
            update_near(i);
        }
    }
    remember_resting_layout();
    // Bodies at rest get no prediction: every pair they could take part in has a moving body,
    // whose prediction covers it.
    for (std::size_t i = 0; i < pos.size(); ++i) {
        if (moving[i]) {
            predict(i);
        }
    }
}

void ExactEngine::Impl::restore_resting_box(std::size_t i) {
    box_dirty[i] = 1;
    sweep_x0[i] = cached_sweep[4 * i];
    sweep_y0[i] = cached_sweep[4 * i + 1];
    sweep_x1[i] = cached_sweep[4 * i + 2];
    sweep_y1[i] = cached_sweep[4 * i + 3];
    box_x0[i] = cached_box[4 * i];
    box_y0[i] = cached_box[4 * i + 1];
    box_x1[i] = cached_box[4 * i + 2];
    box_y1[i] = cached_box[4 * i + 3];
}

// Called when every near[] row is current and before any event: keeps the boxes and rows of
// the bodies at rest for the next run's set-up.
void ExactEngine::Impl::remember_resting_layout() {
    const std::size_t n = pos.size();
    resting_cached = use_near ? active_mask & ~moving_mask : 0;
    cached_sweep.resize(4 * n);
    cached_box.resize(4 * n);
    cached_near.resize(n);
    for (std::uint64_t bits = resting_cached; bits != 0; bits &= bits - 1) {
        const auto i = static_cast<std::size_t>(std::countr_zero(bits));
        cached_sweep[4 * i] = sweep_x0[i];
        cached_sweep[4 * i + 1] = sweep_y0[i];
        cached_sweep[4 * i + 2] = sweep_x1[i];
        cached_sweep[4 * i + 3] = sweep_y1[i];
        cached_box[4 * i] = box_x0[i];
        cached_box[4 * i + 1] = box_y0[i];
        cached_box[4 * i + 2] = box_x1[i];
        cached_box[4 * i + 3] = box_y1[i];
        cached_near[i] = near[i] & resting_cached;
    }
}

void ExactEngine::Impl::run_events() {
    // The key of the end time: 0 when there is no end time. With travel keys it is measured
    // from now, so it is recomputed for each event.
    double key_until = det::exp(-k * options.until_s);
    std::vector<int>& seeds = event_seeds;
    long pops = 0;
    while (!next.empty()) {
        const std::size_t first = earliest();
        if (next[first].kind == Next::None) {
            break;
        }
        const Prediction event = next[first];
        if (travel_keys) {
            key_until = -(u_now * travel_factor_s(k, options.until_s - now));
        }
        if (event.key < key_until) {
            advance(key_until);
            now = options.until_s; // exact, rather than recomputed from the key
            now_stale = false;
            return;
        }
        // Every pop normally emits at least one event; the pop count guards the bound even if
        // rounding ever made a predicted event a no-op.
        ++pops;
        if (result.stats.events >= config.max_events || pops > 4L * config.max_events ||
            result.stats.pair_tests >= detail::kMaxPairTests) {
            result.truncated = true;
            for (std::size_t i = 0; i < pos.size(); ++i) {
                if (moving[i]) {
                    stop_body(i);
                }
            }
            return;
        }
        advance(event.key);
        seeds.assign(1, static_cast<int>(first));
        switch (event.kind) {
        case Next::Stop:
            stop_body(first);
            break;
        case Next::Pocket:
            pocket_body(first, event.other);
            break;
        case Next::Pair:
            seeds.push_back(event.other);
            process_instant(seeds);
            break;
        case Next::Cushion:
            process_instant(seeds);
            break;
        case Next::None:
            break;
        }
        // Recompute the seeds, every body changed at this instant, and every body whose
        // prediction names one of them.
        for (int s : seeds) {
            mark_touched(static_cast<std::size_t>(s));
        }
        if (use_near) {
            std::uint64_t changed = 0;
            for (int t : touched) {
                changed |= std::uint64_t{1} << t;
            }
            // Rows of near[] of every changed body first, so that each prediction reads current
            // rows; then the predictions in index order.
            std::uint64_t redo = changed;
            for (std::uint64_t bits = changed; bits != 0; bits &= bits - 1) {
                const auto t = static_cast<std::size_t>(std::countr_zero(bits));
                redo |= watchers[t];
                if (active[t] && box_dirty[t]) {
                    update_near(t);
                }
            }
            for (; redo != 0; redo &= redo - 1) {
                predict(static_cast<std::size_t>(std::countr_zero(redo)));
            }
            clear_touched();
            continue;
        }
        for (std::size_t j = 0; j < next.size(); ++j) {
            const bool names_changed =
                next[j].kind == Next::Pair && is_touched[static_cast<std::size_t>(next[j].other)];
            if (is_touched[j] || names_changed) {
                predict(j);
            }
        }
        clear_touched();
    }
}

void ExactEngine::Impl::finish() {
    result.end_time_s = time_now();
    for (std::size_t i = 0; i < pos.size(); ++i) {
        Body& b = result.bodies[i];
        b.pos_px = active[i] ? pos[i] : pocketed_at[i];
        b.vel_px_s = vel[i];
        b.pocketed = active[i] == 0;
    }
}

} // namespace carrom
