// The exact event-driven engine. Invariants between events:
//   - pos/vel of every body are exact (to rounding) at time `now`;
//   - next[i] holds the earliest event of body i that is still valid: its own stop, cushion or
//     pocket, or its first contact with another body given both current trajectories. When a
//     body's trajectory changes, it and every body whose prediction names it are recomputed;
//     the global next event is the earliest over next[], i.e. the largest key in keys[] (see
//     docs/physics.md, "Event queue").
//   - bodies at rest have no events of their own; a pair with both bodies at rest is never solved.
//     A body that has been at rest since the start has no prediction at all (next[i] is None):
//     the prediction of every moving body covers its pairs with such bodies, which never change.
//     A body that comes to rest later keeps one, which covers its pairs with the moving bodies
//     whose predictions took it as moving (tests/common/exact_stiff_test.cpp,
//     ACoinThatStopsInAMoversPathIsStillHit).
//   - with at most 64 bodies: near[] is symmetric and current for every body whose box_dirty is
//     0; every dirty row is recomputed before a prediction reads near[]; watchers[o] holds
//     exactly the bodies whose next[] is a Pair naming o.

#include "carrom/exact_engine.hpp"

#include "contact_solver.hpp"
#include "contact_time.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace carrom {

using detail::Contact;
using detail::kApproachTolerancePxS;
using detail::kNever;
using detail::kTouchTolerancePx;

namespace {

enum class Next : std::uint8_t { None, Pair, Cushion, Pocket, Stop };

// Events are keyed by u = e^(-k t), which decreases with time: a prediction made at `now` for
// travel factor s has u = u_now (1 - k s), with no logarithm. Below kTravelKeyDampingPerS the
// keys are -S instead, S = (1 - e^(-k t)) / k the travel factor since t = 0 (S = t when k = 0):
// a prediction has key -(S_now + u_now s). u resolves time only to about 1e-16 / k s, which is
// too coarse for small k (and nothing at k = 0); S resolves it to the rounding of S itself.
// Either way the earliest event has the largest key; kNoEvent is below every real key.
constexpr double kNoEvent = -std::numeric_limits<double>::infinity();

// Damping rates below this (1/s) key events by the travel factor S (see above). At and above it
// the keys are u, whose time resolution (1e-16 / k s) is then finer than 1e-15 s.
constexpr double kTravelKeyDampingPerS = 0.1;

// The work bound of one run besides max_events: after this many pair tests (SimStats::pair_tests,
// about 50 ns each) the run ends as at max_events, flagged truncated. No shot on the standard
// layout comes near it (a break makes about 4,000).
constexpr int kMaxPairTests = 1 << 23;

// The longest travel factor a moving body's path box is drawn for when keys are travel factors,
// s: enough to cross any board at 1e-3 px/s; the box is clamped to the cushion range, which the
// path cannot leave before its next event.
constexpr double kLongestBoxTravelS = 1e12;

struct Prediction {
    double key = kNoEvent;
    Next kind = Next::None;
    int other = -1; // body index (Pair), cushion index (Cushion), pocket index (Pocket)
};

// Axis-aligned box, px.
struct Box {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

// Rounds of impacts at one instant after which the remaining cascade is solved as one plastic
// contact group (the remedy for zero-time inelastic collapse; docs/physics.md): the larger of
// kRoundsBeforeCollapse and kCollapseRoundsPerBodySquared m^2, m the bodies the cascade has
// reached. A straight row of m touching bodies struck at one end converges in about 4.3 m^2
// rounds for e from 0.5 to 1 (ExactCradle), well inside the bound; a true zero-time collapse
// never converges and is ended by it.
constexpr long kRoundsBeforeCollapse = 16;
constexpr long kCollapseRoundsPerBodySquared = 8;

// Where pocketed bodies are kept, px: far enough that no distance or box test ever passes.
constexpr Vec2 kFarAway{1e30, 1e30};

// The overlap tolerance of validate_scene's default, px.
constexpr double kOverlapTolerancePx = 1e-9;

// A float below (above) the finite x, px: x is moved outwards by 1e-3 px plus 1e-6 of |x|, more
// than the relative rounding of the conversion (2^-24), so the float box contains the double
// box. Branch-free, unlike std::nextafter.
float float_down(double x) {
    return static_cast<float>(x - (std::fabs(x) * 1e-6 + 1e-3));
}
float float_up(double x) {
    return static_cast<float>(x + (std::fabs(x) * 1e-6 + 1e-3));
}

int cushion_index(Vec2 normal) {
    if (normal.x < 0.0) {
        return kCushionLeft;
    }
    if (normal.x > 0.0) {
        return kCushionRight;
    }
    return normal.y < 0.0 ? kCushionTop : kCushionBottom;
}

} // namespace

struct ExactEngine::Impl {
    explicit Impl(const PhysicsConfig& c);

    PhysicsConfig config;
    double k = 0.0;           // damping, 1/s
    double inv_k = 0.0;       // s (infinite when k = 0)
    bool travel_keys = false; // k < kTravelKeyDampingPerS: keys are -S (see kNoEvent)
    std::array<Vec2, 4> pockets{};
    std::array<Box, 4> pocket_boxes{};
    // A path box with x0 > pocket_gap.x0 and x1 < pocket_gap.x1 (or the same in y) lies between
    // the pocket boxes of the left and right (top and bottom) pockets and overlaps none.
    Box pocket_gap{};

    // Per body, in input order.
    std::vector<int> ids;
    std::vector<Vec2> pos;      // px, at `now`; far outside the board once pocketed
    std::vector<Vec2> vel;      // px/s, at `now`
    std::vector<double> speed;  // |vel|, px/s
    std::vector<double> radius; // px
    std::vector<double> inv_mass;
    std::vector<double> lo, hi; // cushion limits of the centre, px
    double max_radius = 0.0;    // largest radius in the scene, px
    std::vector<char> active;   // not pocketed
    std::vector<char> moving;   // speed above the stop speed
    // Box covering the rest of each body's current path (radius included), px, stored as
    // separate arrays so the broad-phase loop runs without branches.
    std::vector<double> sweep_x0, sweep_y0, sweep_x1, sweep_y1;
    // The same boxes rounded outwards to float (each float box contains the double box), padded
    // to a multiple of 4 with empty boxes, so SSE tests four bodies at a time in box_overlaps.
    std::vector<float> box_x0, box_y0, box_x1, box_y1;
    std::vector<Vec2> pocketed_at; // where a pocketed body entered its pocket, px
    // near[i] bit j (== near[j] bit i): the path boxes of i and j overlap. predict(i) runs after
    // every change of i's box and updates row and column i, so two bodies can touch only if
    // their bit is set. Used when the scene has at most 64 bodies; larger scenes test every pair.
    std::vector<std::uint64_t> near;
    bool use_near = false;
    std::uint64_t box_overlaps(std::size_t i) const;
    // Per-instant cache of touch_mask(i): valid when touch_stamp[i] == instant_stamp.
    std::vector<std::uint64_t> touch_bits;
    std::vector<std::uint64_t> touch_stamp;
    std::uint64_t instant_stamp = 0;     // incremented by process_instant; never 0 inside one
    std::vector<std::uint8_t> wall_bits; // bits 0-3: touching the left, right, top, bottom cushion
    std::uint64_t touch_mask(std::size_t a);
    void collect_impacts_near();

    std::vector<Prediction> next;
    std::vector<double> keys; // keys[i] == next[i].key, contiguous for the scan for the maximum
    // With use_near (at most 64 bodies), bit masks over body indices:
    //   watchers[o] bit j: next[j] is a Pair event naming o;
    //   active_mask / moving_mask bit i: active[i] / moving[i];
    //   box_dirty[i]: body i's path box changed since row i of near[] was last computed.
    std::vector<std::uint64_t> watchers;
    std::uint64_t active_mask = 0, moving_mask = 0;
    std::vector<char> box_dirty;
    void set_next(std::size_t i, const Prediction& p);
    void update_near(std::size_t i);
    std::vector<int> moving_list; // indices of moving bodies, rebuilt when stale
    bool moving_list_stale = true;

    // Scratch for one instant of simultaneous impacts.
    std::vector<Contact> contacts;
    std::vector<int> frontier, next_frontier, touched, cluster, root, event_seeds;
    std::vector<char> in_frontier, is_touched, in_cluster;
    std::vector<double> solve_inv_mass; // 0 for bodies pinned by the stop rule at this instant
    detail::ContactSolver solver;

    // The current time is u_now = e^(-k now) (with travel_keys: travel_now = S(now)). `now` (s)
    // is derived from it only when an event or segment is recorded or the run ends (now_stale:
    // not yet derived since the last advance).
    double now = 0.0;        // s
    double u_now = 1.0;      // e^(-k now)
    double travel_now = 0.0; // S(now) = (1 - e^(-k now)) / k, s; kept only with travel_keys
    bool now_stale = false;
    double time_now() {
        if (now_stale) {
            if (!travel_keys) {
                now = -std::log(u_now) * inv_k;
            } else {
                // t = -ln(1 - k S) / k = S (-ln(1 - x) / x), x = k S, which is 1 at x = 0.
                const double x = k * travel_now;
                now = x == 0.0 ? travel_now : travel_now * (-std::log1p(-x) / x);
            }
            now_stale = false;
        }
        return now;
    }
    // The key of the time at which the travel factor from now is s (s >= 0).
    double key_after(double s) const {
        return travel_keys ? -(travel_now + u_now * s) : u_now * (1.0 - k * s);
    }
    SimOptions options;
    SimResult result;

    // The last scene that passed validate_scene (empty after a rejected one).
    std::vector<Body> validated;
    std::uint64_t unchanged_since_validated(std::span<const Body> bodies) const;

    void load(std::span<const Body> bodies);
    void settle_initial_state(std::uint64_t unchanged);

    // The path boxes and near[] rows that the last run's set-up computed for the bodies that
    // lay at rest on the board, kept for the next run (use_near only): bit i of resting_cached
    // says entry i holds body i's box and its row restricted to resting_cached. A body that is
    // bit for bit the same in the next scene has the same box and the same overlaps with the
    // other such bodies, so set-up copies them instead of computing them (see docs/physics.md).
    std::uint64_t resting_cached = 0;
    std::vector<double> cached_sweep; // 4 per body: x0, y0, x1, y1
    std::vector<float> cached_box;    // 4 per body: x0, y0, x1, y1
    std::vector<std::uint64_t> cached_near;
    void restore_resting_box(std::size_t i);
    void remember_resting_layout();
    void run_events();
    void finish();

    double stop_s(std::size_t i) const { return (1.0 - config.stop_speed_px_s / speed[i]) * inv_k; }
    void refresh(std::size_t i);
    void advance(double key);
    void predict(std::size_t i);
    void emit(EventKind kind, std::size_t a, int b, double impulse);
    void record_segment(std::size_t i);
    void stop_body(std::size_t i);
    void pocket_body(std::size_t i, int pocket);
    void process_instant(std::span<const int> seeds);
    bool isolated_pair_round(std::size_t a, std::size_t b);
    bool isolated_pair(std::size_t a, std::size_t b);
    bool approaching_pair(std::size_t lo_i, std::size_t hi_i, Contact& out) const;
    bool collect_isolated_pair();
    bool collect_lone_body();
    void collect_walls(std::size_t a);
    void collect_impacts();
    void collect_cluster();
    void solve_groups();
    void mark_touched(std::size_t i);
    void clear_touched();
    double restitution(double approach_px_s, bool cushion) const;
};

ExactEngine::Impl::Impl(const PhysicsConfig& c) : config(c) {
    k = c.damping_per_s;
    inv_k = 1.0 / k;
    travel_keys = k < kTravelKeyDampingPerS;
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
    travel_now = 0.0;
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

void ExactEngine::Impl::refresh(std::size_t i) {
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
        end += v * std::min((1.0 - config.stop_speed_px_s / sp) * inv_k, kLongestBoxTravelS);
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
    box_x0[i] = float_down(x0);
    box_y0[i] = float_down(y0);
    box_x1[i] = float_up(x1);
    box_y1[i] = float_up(y1);
}

void ExactEngine::Impl::emit(EventKind kind, std::size_t a, int b, double impulse) {
    ++result.stats.events;
    if (options.record_events) {
        result.events.push_back({time_now(), kind, ids[a], b, impulse, pos[a]});
    }
}

void ExactEngine::Impl::record_segment(std::size_t i) {
    if (options.record_trajectory) {
        result.trajectory.segments.push_back(
            {time_now(), static_cast<int>(i), pos[i], vel[i], active[i] == 0});
    }
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

// Moves every body to the time whose key is `key` (a time not before now).
void ExactEngine::Impl::advance(double key) {
    double decay = 0.0; // e^(-k dt)
    double s = 0.0;     // (1 - e^(-k dt)) / k, s
    if (!travel_keys) {
        if (key >= u_now) {
            return;
        }
        decay = key / u_now;
        s = (1.0 - decay) * inv_k;
    } else {
        // key = -(S_now + u_now s): S(now + dt) = S_now + e^(-k now) (1 - e^(-k dt)) / k.
        if (-key <= travel_now) {
            return;
        }
        s = (-key - travel_now) / u_now;
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
    } else {
        u_now *= decay;
        travel_now = -key;
    }
    now_stale = true;
}

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

// Recomputes row i of near[] from the current boxes and keeps near symmetric by flipping bit i
// of every body whose bit in row i changed. Only for active bodies (a pocketed body's row is
// kept up to date by the flips of the others).
void ExactEngine::Impl::update_near(std::size_t i) {
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
std::uint64_t ExactEngine::Impl::box_overlaps(std::size_t i) const {
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

double ExactEngine::Impl::restitution(double approach_px_s, bool cushion) const {
    if (approach_px_s < config.restitution_floor_px_s) {
        return 0.0;
    }
    return cushion ? config.cushion_restitution : config.disc_restitution;
}

// Bit b set: bodies a and b touch (gap <= kTouchTolerancePx) and their path boxes overlap
// (near[a] bit b). Positions and near[] do not change during an instant, so process_instant
// computes each body's mask at most once per instant (touch_stamp == instant_stamp).
std::uint64_t ExactEngine::Impl::touch_mask(std::size_t a) {
    if (touch_stamp[a] == instant_stamp) {
        return touch_bits[a];
    }
    const Vec2 pa = pos[a];
    const double ra = radius[a];
    std::uint64_t mask = 0;
    for (std::uint64_t bits = near[a]; bits != 0; bits &= bits - 1) {
        const auto b = static_cast<std::size_t>(std::countr_zero(bits));
        const Vec2 d = pos[b] - pa;
        const double touch = ra + radius[b] + kTouchTolerancePx;
        const bool touching = length_squared(d) <= touch * touch;
        mask |= static_cast<std::uint64_t>(touching) << b;
    }
    const Vec2 lo_gap = pa - Vec2{lo[a], lo[a]};
    const Vec2 hi_gap = Vec2{hi[a], hi[a]} - pa;
    wall_bits[a] = static_cast<std::uint8_t>(
        (lo_gap.x <= kTouchTolerancePx ? 1 : 0) | (hi_gap.x <= kTouchTolerancePx ? 2 : 0) |
        (lo_gap.y <= kTouchTolerancePx ? 4 : 0) | (hi_gap.y <= kTouchTolerancePx ? 8 : 0));
    touch_stamp[a] = instant_stamp;
    touch_bits[a] = mask;
    return mask;
}

// collect_impacts for scenes of at most 64 bodies: the same contacts in the same order, from the
// per-instant touch masks (touching pairs) and wall bits (touching cushions).
void ExactEngine::Impl::collect_impacts_near() {
    contacts.clear();
    std::uint64_t frontier_mask = 0;
    for (int a : frontier) {
        frontier_mask |= std::uint64_t{1} << a;
    }
    const Vec2* const p = pos.data();
    const Vec2* const v = vel.data();
    const double* const im = solve_inv_mass.data();
    for (int ai : frontier) {
        const auto a = static_cast<std::size_t>(ai);
        if (!active[a]) {
            continue;
        }
        // Touching active partners; a pair of two frontier bodies is visited from the lower one.
        const std::uint64_t lower = (std::uint64_t{1} << a) - 1;
        std::uint64_t bits = touch_mask(a) & active_mask & ~(frontier_mask & lower);
        const Vec2 pa = p[a];
        const Vec2 va = v[a];
        for (; bits != 0; bits &= bits - 1) {
            const auto b = static_cast<std::size_t>(std::countr_zero(bits));
            if (im[a] == 0.0 && im[b] == 0.0) {
                continue;
            }
            const Vec2 d = p[b] - pa;
            const double dist = std::sqrt(length_squared(d));
            const Vec2 normal = d * (1.0 / dist);
            const double u = dot(v[b] - va, normal);
            if (u < -kApproachTolerancePxS) {
                contacts.push_back({ai, static_cast<int>(b), normal, restitution(-u, false), 0.0});
            }
        }
        collect_walls(a);
    }
}

// Appends the approaching cushion contacts of body a (its wall bits are current).
void ExactEngine::Impl::collect_walls(std::size_t a) {
    const unsigned walls = wall_bits[a];
    if (walls == 0) {
        return;
    }
    const Vec2 va = vel[a];
    const int ai = static_cast<int>(a);
    if ((walls & 1U) != 0 && va.x < -kApproachTolerancePxS) {
        contacts.push_back({ai, -1, {-1.0, 0.0}, restitution(dot(va, {-1.0, 0.0}), true), 0.0});
    }
    if ((walls & 2U) != 0 && va.x > kApproachTolerancePxS) {
        contacts.push_back({ai, -1, {1.0, 0.0}, restitution(dot(va, {1.0, 0.0}), true), 0.0});
    }
    if ((walls & 4U) != 0 && va.y < -kApproachTolerancePxS) {
        contacts.push_back({ai, -1, {0.0, -1.0}, restitution(dot(va, {0.0, -1.0}), true), 0.0});
    }
    if ((walls & 8U) != 0 && va.y > kApproachTolerancePxS) {
        contacts.push_back({ai, -1, {0.0, 1.0}, restitution(dot(va, {0.0, 1.0}), true), 0.0});
    }
}

// collect_impacts_near for a frontier of one active body that touches no other active body: its
// cushion contacts only. Returns false, collecting nothing, otherwise.
bool ExactEngine::Impl::collect_lone_body() {
    const auto a = static_cast<std::size_t>(frontier[0]);
    if (!active[a] || (touch_mask(a) & active_mask) != 0) {
        return false;
    }
    contacts.clear();
    collect_walls(a);
    return true;
}

// Impacts at `now`: touching, approaching contacts that involve a body of the frontier.
void ExactEngine::Impl::collect_impacts() {
    if (use_near) {
        collect_impacts_near();
        return;
    }
    contacts.clear();
    for (int a : frontier) {
        in_frontier[static_cast<std::size_t>(a)] = 1;
    }
    for (int ai : frontier) {
        const auto a = static_cast<std::size_t>(ai);
        if (!active[a]) {
            continue;
        }
        const Vec2 pa = pos[a];
        const double reach_max = radius[a] + max_radius + kTouchTolerancePx;
        const std::uint64_t candidates = use_near ? touch_mask(a) : 0;
        const std::size_t count = use_near ? 64 : pos.size();
        std::uint64_t bits = candidates;
        for (std::size_t scan = 0; scan < count; ++scan) {
            std::size_t b = scan;
            if (use_near) {
                if (bits == 0) {
                    break;
                }
                b = static_cast<std::size_t>(std::countr_zero(bits));
                bits &= bits - 1;
            }
            // Cheapest rejection first: most bodies are far away.
            const Vec2 d = pos[b] - pa;
            if (std::fabs(d.x) > reach_max || std::fabs(d.y) > reach_max || b == a || !active[b] ||
                (in_frontier[b] && b < a) ||
                (solve_inv_mass[a] == 0.0 && solve_inv_mass[b] == 0.0)) {
                continue;
            }
            const double reach = radius[a] + radius[b];
            const double dist2 = length_squared(d);
            const double touch = reach + kTouchTolerancePx;
            if (dist2 > touch * touch) {
                continue;
            }
            const double dist = std::sqrt(dist2);
            const Vec2 normal = d * (1.0 / dist);
            const double u = dot(vel[b] - vel[a], normal);
            if (u < -kApproachTolerancePxS) {
                contacts.push_back({ai, static_cast<int>(b), normal, restitution(-u, false), 0.0});
            }
        }
        const Vec2 p = pos[a];
        const Vec2 v = vel[a];
        const std::pair<bool, Vec2> walls[] = {
            {p.x - lo[a] <= kTouchTolerancePx && v.x < -kApproachTolerancePxS, {-1.0, 0.0}},
            {hi[a] - p.x <= kTouchTolerancePx && v.x > kApproachTolerancePxS, {1.0, 0.0}},
            {p.y - lo[a] <= kTouchTolerancePx && v.y < -kApproachTolerancePxS, {0.0, -1.0}},
            {hi[a] - p.y <= kTouchTolerancePx && v.y > kApproachTolerancePxS, {0.0, 1.0}}};
        for (const auto& [touching, n] : walls) {
            if (touching) {
                const double approach = dot(v, n);
                contacts.push_back({ai, -1, n, restitution(approach, true), 0.0});
            }
        }
    }
    for (int a : frontier) {
        in_frontier[static_cast<std::size_t>(a)] = 0;
    }
}

// The collapse remedy: every touching contact of the cluster of bodies that touch the frontier
// (transitively), approaching or not, solved together with restitution 0. Afterwards no
// contact of the cluster approaches, so the cascade at this instant ends.
void ExactEngine::Impl::collect_cluster() {
    cluster.clear();
    for (int a : frontier) {
        if (!in_cluster[static_cast<std::size_t>(a)]) {
            in_cluster[static_cast<std::size_t>(a)] = 1;
            cluster.push_back(a);
        }
    }
    contacts.clear();
    for (std::size_t q = 0; q < cluster.size(); ++q) {
        const auto a = static_cast<std::size_t>(cluster[q]);
        for (std::size_t b = 0; b < pos.size(); ++b) {
            if (b == a || !active[b]) {
                continue;
            }
            const Vec2 d = pos[b] - pos[a];
            const double dist = length(d);
            if (dist - radius[a] - radius[b] > kTouchTolerancePx) {
                continue;
            }
            if (!in_cluster[b]) {
                in_cluster[b] = 1;
                cluster.push_back(static_cast<int>(b));
            }
        }
    }
    for (int ai : cluster) {
        const auto a = static_cast<std::size_t>(ai);
        for (int bi : cluster) {
            const auto b = static_cast<std::size_t>(bi);
            if (b <= a || (solve_inv_mass[a] == 0.0 && solve_inv_mass[b] == 0.0)) {
                continue;
            }
            const Vec2 d = pos[b] - pos[a];
            const double dist = length(d);
            if (dist - radius[a] - radius[b] <= kTouchTolerancePx) {
                contacts.push_back({ai, bi, d * (1.0 / dist), 0.0, 0.0});
            }
        }
        if (solve_inv_mass[a] == 0.0) {
            continue;
        }
        const Vec2 p = pos[a];
        const std::pair<bool, Vec2> walls[] = {{p.x - lo[a] <= kTouchTolerancePx, {-1.0, 0.0}},
                                               {hi[a] - p.x <= kTouchTolerancePx, {1.0, 0.0}},
                                               {p.y - lo[a] <= kTouchTolerancePx, {0.0, -1.0}},
                                               {hi[a] - p.y <= kTouchTolerancePx, {0.0, 1.0}}};
        for (const auto& [touching, n] : walls) {
            if (touching) {
                contacts.push_back({ai, -1, n, 0.0, 0.0});
            }
        }
    }
    for (int a : cluster) {
        in_cluster[static_cast<std::size_t>(a)] = 0;
    }
}

// Splits the contacts into groups connected through shared movable bodies and resolves each
// group simultaneously. Group order and the order inside a group follow the contact list, which
// is deterministic.
void ExactEngine::Impl::solve_groups() {
    if (contacts.size() == 1) {
        solver.resolve(contacts, vel, solve_inv_mass);
        return;
    }
    for (const Contact& c : contacts) {
        root[static_cast<std::size_t>(c.a)] = c.a;
        if (c.b >= 0) {
            root[static_cast<std::size_t>(c.b)] = c.b;
        }
    }
    auto find = [this](int x) {
        while (root[static_cast<std::size_t>(x)] != x) {
            x = root[static_cast<std::size_t>(x)] =
                root[static_cast<std::size_t>(root[static_cast<std::size_t>(x)])];
        }
        return x;
    };
    for (const Contact& c : contacts) {
        if (c.b >= 0) {
            const int ra = find(c.a);
            const int rb = find(c.b);
            root[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
        }
    }
    // Stable insertion sort by group: contact lists are short, and this allocates nothing.
    for (std::size_t i = 1; i < contacts.size(); ++i) {
        const Contact c = contacts[i];
        const int key = find(c.a);
        std::size_t j = i;
        for (; j > 0 && find(contacts[j - 1].a) > key; --j) {
            contacts[j] = contacts[j - 1];
        }
        contacts[j] = c;
    }
    std::size_t begin = 0;
    while (begin < contacts.size()) {
        std::size_t end = begin + 1;
        while (end < contacts.size() && find(contacts[end].a) == find(contacts[begin].a)) {
            ++end;
        }
        solver.resolve(std::span<Contact>(contacts).subspan(begin, end - begin), vel,
                       solve_inv_mass);
        begin = end;
    }
}

void ExactEngine::Impl::mark_touched(std::size_t i) {
    if (!is_touched[i]) {
        is_touched[i] = 1;
        touched.push_back(static_cast<int>(i));
    }
}

// Resolves everything that happens at `now`, starting from the seed bodies: rounds of
// simultaneous impacts until no touching contact approaches; then the stop rule for bodies left
// below the stop speed (they are pinned for the rest of the instant, and bodies still pushing
// into them are resolved against them). Bounded: each round either ends the cascade, or after
// max(kRoundsBeforeCollapse, kCollapseRoundsPerBodySquared m^2) rounds (m the bodies reached)
// the cluster is solved plastically; each stop pass pins at least
// one more body.
void ExactEngine::Impl::process_instant(std::span<const int> seeds) {
    ++instant_stamp;
    clear_touched();
    frontier.assign(seeds.begin(), seeds.end());
    for (int s : seeds) {
        mark_touched(static_cast<std::size_t>(s));
    }
    long rounds = 0;
    if (use_near && seeds.size() == 2 &&
        isolated_pair_round(static_cast<std::size_t>(seeds[0]),
                            static_cast<std::size_t>(seeds[1]))) {
        rounds = 1;
    }
    const double stop2 = config.stop_speed_px_s * config.stop_speed_px_s;
    const auto bodies = static_cast<long>(pos.size()) + 1;
    const long max_rounds =
        (kRoundsBeforeCollapse + 2) * bodies + kCollapseRoundsPerBodySquared * bodies * bodies;
    while (!frontier.empty() && rounds < max_rounds) {
        const bool collected = use_near && ((frontier.size() == 2 && collect_isolated_pair()) ||
                                            (frontier.size() == 1 && collect_lone_body()));
        if (!collected) {
            collect_impacts();
        }
        if (contacts.empty()) {
            // The cascade has ended: apply the stop rule to every body changed at this instant.
            next_frontier.clear();
            for (int ti : touched) {
                const auto t = static_cast<std::size_t>(ti);
                const double v2 = length_squared(vel[t]);
                if (active[t] && v2 > 0.0 && v2 <= stop2) {
                    vel[t] = {};
                    emit(EventKind::Stop, t, -1, 0.0);
                    solve_inv_mass[t] = 0.0;
                    next_frontier.push_back(ti);
                }
            }
            frontier.swap(next_frontier);
            continue;
        }
        ++rounds;
        ++result.stats.contact_rounds;
        const auto reached = static_cast<long>(touched.size());
        if (rounds >
            std::max(kRoundsBeforeCollapse, kCollapseRoundsPerBodySquared * reached * reached)) {
            collect_cluster();
            ++result.stats.collapse_solves;
        }
        solve_groups();
        next_frontier.clear();
        std::uint64_t in_next = 0; // with use_near: bit i set when i is in next_frontier
        for (const Contact& c : contacts) {
            if (c.impulse <= 0.0) {
                continue;
            }
            const auto a = static_cast<std::size_t>(c.a);
            if (c.b >= 0) {
                ++result.collision_counts[a];
                ++result.collision_counts[static_cast<std::size_t>(c.b)];
                emit(EventKind::Collision, a, ids[static_cast<std::size_t>(c.b)], c.impulse);
            } else {
                emit(EventKind::Cushion, a, cushion_index(c.normal), c.impulse);
            }
            for (int body : {c.a, c.b}) {
                if (body < 0 || solve_inv_mass[static_cast<std::size_t>(body)] == 0.0) {
                    continue;
                }
                if (use_near) {
                    const std::uint64_t bit = std::uint64_t{1} << body;
                    if ((in_next & bit) != 0) {
                        continue;
                    }
                    in_next |= bit;
                } else if (std::find(next_frontier.begin(), next_frontier.end(), body) !=
                           next_frontier.end()) {
                    continue;
                }
                next_frontier.push_back(body);
                mark_touched(static_cast<std::size_t>(body));
            }
        }
        frontier.swap(next_frontier);
    }
    // The touched list stays for the caller, which recomputes those bodies' predictions.
    for (int ti : touched) {
        const auto t = static_cast<std::size_t>(ti);
        solve_inv_mass[t] = inv_mass[t];
        refresh(t);
        record_segment(t);
    }
}

// The first round of process_instant for a pair event when the two bodies touch each other and
// nothing else (no other body, no cushion): the same contact, solve and bookkeeping as the
// general round (collect_impacts_near, solve_groups), without its loops. Returns false, having
// changed nothing but the per-instant touch cache, when the pair is not isolated or does not
// approach; the general round then runs.
bool ExactEngine::Impl::isolated_pair_round(std::size_t a, std::size_t b) {
    if (!isolated_pair(a, b)) {
        return false;
    }
    // As in collect_impacts_near: the pair is visited from its lower index.
    const std::size_t lo_i = std::min(a, b);
    const std::size_t hi_i = std::max(a, b);
    if (solve_inv_mass[lo_i] == 0.0 && solve_inv_mass[hi_i] == 0.0) {
        return false;
    }
    Contact contact{};
    if (!approaching_pair(lo_i, hi_i, contact)) {
        return false;
    }
    contacts.clear();
    contacts.push_back(contact);
    ++result.stats.contact_rounds;
    solver.resolve(contacts, vel, solve_inv_mass);
    frontier.clear();
    const Contact& c = contacts.front();
    if (c.impulse > 0.0) {
        ++result.collision_counts[lo_i];
        ++result.collision_counts[hi_i];
        emit(EventKind::Collision, lo_i, ids[hi_i], c.impulse);
        for (std::size_t body : {lo_i, hi_i}) {
            if (solve_inv_mass[body] != 0.0) {
                frontier.push_back(static_cast<int>(body));
                mark_touched(body);
            }
        }
    }
    return true;
}

// Bodies a and b (use_near) are distinct, active, touch each other and touch nothing else: no
// other active body and no cushion.
bool ExactEngine::Impl::isolated_pair(std::size_t a, std::size_t b) {
    if (!active[a] || !active[b] || a == b) {
        return false;
    }
    const std::uint64_t bit_a = std::uint64_t{1} << a;
    const std::uint64_t bit_b = std::uint64_t{1} << b;
    return (touch_mask(a) & active_mask) == bit_b && (touch_mask(b) & active_mask) == bit_a &&
           wall_bits[a] == 0 && wall_bits[b] == 0;
}

// collect_impacts_near for a frontier of two bodies that form an isolated pair: the same
// contacts (none, or the pair's, visited from its lower index). Returns false, and collects
// nothing, when the frontier is not such a pair.
bool ExactEngine::Impl::collect_isolated_pair() {
    const auto a = static_cast<std::size_t>(frontier[0]);
    const auto b = static_cast<std::size_t>(frontier[1]);
    if (!isolated_pair(a, b)) {
        return false;
    }
    contacts.clear();
    const std::size_t lo_i = std::min(a, b);
    const std::size_t hi_i = std::max(a, b);
    if (solve_inv_mass[lo_i] == 0.0 && solve_inv_mass[hi_i] == 0.0) {
        return true;
    }
    Contact contact{};
    if (approaching_pair(lo_i, hi_i, contact)) {
        contacts.push_back(contact);
    }
    return true;
}

// The contact of two touching bodies (lo_i < hi_i) as collect_impacts_near builds it, when they
// approach (normal relative speed above the approach tolerance); false otherwise.
bool ExactEngine::Impl::approaching_pair(std::size_t lo_i, std::size_t hi_i, Contact& out) const {
    const Vec2 d = pos[hi_i] - pos[lo_i];
    const Vec2 w = vel[hi_i] - vel[lo_i];
    // Clearly moving apart (the pair just exchanged its impulse, say): w . d exceeds the
    // rounding of the normalised form below (a few 1e-16 of its terms) by far, so u > 0 there
    // too and the answer is the same, without the square root and the division.
    const double wx_dx = w.x * d.x;
    const double wy_dy = w.y * d.y;
    if (wx_dx + wy_dy > 1e-12 * (std::fabs(wx_dx) + std::fabs(wy_dy))) {
        return false;
    }
    const double dist = std::sqrt(length_squared(d));
    const Vec2 normal = d * (1.0 / dist);
    const double u = dot(w, normal);
    if (!(u < -kApproachTolerancePxS)) {
        return false;
    }
    out = {static_cast<int>(lo_i), static_cast<int>(hi_i), normal, restitution(-u, false), 0.0};
    return true;
}

void ExactEngine::Impl::clear_touched() {
    for (int t : touched) {
        is_touched[static_cast<std::size_t>(t)] = 0;
    }
    touched.clear();
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

// unchanged: bit i set when body i is bit for bit body i of the previous run's scene.
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

void ExactEngine::Impl::run_events() {
    // The key of the end time: 0 (or -infinity with travel keys) when there is no end time.
    double key_until = std::exp(-k * options.until_s);
    if (travel_keys) {
        key_until = -travel_factor_s(k, options.until_s);
    }
    std::vector<int>& seeds = event_seeds;
    long pops = 0;
    while (!next.empty()) {
        // The largest key; ties go to the lower index.
        std::size_t first = 0;
        {
            const double* const kp = keys.data();
            const std::size_t count = keys.size();
#if defined(__SSE2__)
            __m128d top = _mm_loadu_pd(kp);
            for (std::size_t i = 2; i < count; i += 2) {
                top = _mm_max_pd(top, _mm_loadu_pd(kp + i));
            }
            const double first_key =
                std::max(_mm_cvtsd_f64(top), _mm_cvtsd_f64(_mm_unpackhi_pd(top, top)));
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
        }
        if (next[first].kind == Next::None) {
            break;
        }
        const Prediction event = next[first];
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
            result.stats.pair_tests >= kMaxPairTests) {
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

namespace {

// Same bits: doubles compared by representation, so -0.0 differs from 0.0 and NaN from nothing.
bool same_body(const Body& a, const Body& b) {
    return a.id == b.id && a.kind == b.kind && a.pocketed == b.pocketed &&
           std::bit_cast<std::uint64_t>(a.pos_px.x) == std::bit_cast<std::uint64_t>(b.pos_px.x) &&
           std::bit_cast<std::uint64_t>(a.pos_px.y) == std::bit_cast<std::uint64_t>(b.pos_px.y) &&
           std::bit_cast<std::uint64_t>(a.vel_px_s.x) ==
               std::bit_cast<std::uint64_t>(b.vel_px_s.x) &&
           std::bit_cast<std::uint64_t>(a.vel_px_s.y) == std::bit_cast<std::uint64_t>(b.vel_px_s.y);
}

} // namespace

// Bit i set: bodies[i] is bit for bit body i of the last validated scene (the same engine, so
// the same config and tolerance). 0 when the sizes differ or there are more than 64 bodies.
std::uint64_t ExactEngine::Impl::unchanged_since_validated(std::span<const Body> bodies) const {
    if (bodies.size() != validated.size() || bodies.size() > 64) {
        return 0;
    }
    std::uint64_t mask = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        mask |= static_cast<std::uint64_t>(same_body(bodies[i], validated[i])) << i;
    }
    return mask;
}

ExactEngine::ExactEngine(const PhysicsConfig& config) : impl_(std::make_unique<Impl>(config)) {}
ExactEngine::~ExactEngine() = default;

const PhysicsConfig& ExactEngine::config() const {
    return impl_->config;
}

ExactEngine::Outcome ExactEngine::run(std::span<const Body> bodies, const SimOptions& options) {
    // Bodies identical to those of the last scene that passed validation are known not to
    // overlap one another (a bot's search runs thousands of scenes that differ in the striker).
    const std::uint64_t unchanged = impl_->unchanged_since_validated(bodies);
    if (auto error = validate_scene(impl_->config, bodies, kOverlapTolerancePx, unchanged)) {
        impl_->validated.clear();
        impl_->resting_cached = 0;
        return {std::move(error), nullptr};
    }
    impl_->validated.assign(bodies.begin(), bodies.end());
    impl_->options = options;
    impl_->load(bodies);
    impl_->settle_initial_state(unchanged);
    impl_->run_events();
    impl_->finish();
    return {std::nullopt, &impl_->result};
}

SimulateResult simulate_exact(const PhysicsConfig& config, std::span<const Body> bodies,
                              const SimOptions& options) {
    ExactEngine engine(config);
    ExactEngine::Outcome outcome = engine.run(bodies, options);
    SimulateResult out;
    out.error = std::move(outcome.error);
    if (outcome.result) {
        out.result = *outcome.result;
    }
    return out;
}

} // namespace carrom
