#pragma once
// The state of the exact event-driven engine (ExactEngine::Impl) and the invariants that hold
// between events. Which file owns which part (docs/physics.md, "The engine's files"):
//   engine_state.hpp     this state, its invariants, the small helpers every part uses;
//   broad_phase.hpp      path boxes, near[] rows, box_overlaps, touch_mask (inline: hot);
//   event_queue.cpp      predict and set_next: each body's next event and its key;
//   event_queue.hpp      earliest (the next event) and advance (inline: hot);
//   contact_instant.cpp  process_instant: the contacts of one instant and their solve;
//   engine_run.cpp       load, set-up (settle_initial_state, the resting-layout cache),
//                        run_events, finish;
//   exact_engine.cpp     the public ExactEngine and simulate_exact.
//
// Invariants between events:
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
//   - with at most 64 bodies (use_near): near[] is symmetric and current for every body whose
//     box_dirty is 0; every dirty row is recomputed before a prediction reads near[];
//     watchers[o] holds exactly the bodies whose next[] is a Pair naming o. Larger scenes test
//     every pair instead (the all-pairs path: predict's loop, collect_impacts_all_pairs and
//     moving_list).
//
// Units: px, s, px/s, mass in coin masses; impulses in coin masses times px/s. Body indices are
// input order.

#include "carrom/det_math.hpp"
#include "carrom/exact_engine.hpp"

#include "contact_solver.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace carrom::detail {

// What a body's next event is (its Prediction).
enum class Next : std::uint8_t { None, Pair, Cushion, Pocket, Stop };

// Events are keyed by u = e^(-k t), which decreases with time: a prediction made at `now` for
// travel factor s has u = u_now (1 - k s), with no logarithm. Below kTravelKeyDampingPerS the
// keys are -(S - S_now) instead, S = (1 - e^(-k t)) / k the travel factor since t = 0 (S = t
// when k = 0), measured from the current time: a prediction has key -u_now s, and every advance
// adds the travel it moved to every key. u resolves time only to about 1e-16 / k s, which is too
// coarse for small k (and nothing at k = 0); relative travel factors resolve it to the rounding
// of the time to the event, however long the run has lasted.
// Either way the earliest event has the largest key; kNoEvent is below every real key.
inline constexpr double kNoEvent = -std::numeric_limits<double>::infinity();

// Damping rates below this (1/s) key events by the travel factor S (see above). At and above it
// the keys are u, whose time resolution (1e-16 / k s) is then finer than 1e-15 s.
inline constexpr double kTravelKeyDampingPerS = 0.1;

// The work bound of one run besides max_events: after this many pair tests (SimStats::pair_tests,
// about 50 ns each) the run ends as at max_events, flagged truncated. No shot on the standard
// layout comes near it (a break makes about 4,000).
inline constexpr int kMaxPairTests = 1 << 23;

// The longest travel factor a moving body's path box is drawn for when keys are travel factors,
// s: enough to cross any board at 1e-3 px/s; the box is clamped to the cushion range, which the
// path cannot leave before its next event.
inline constexpr double kLongestBoxTravelS = 1e12;

// A body's next event.
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
inline constexpr long kRoundsBeforeCollapse = 16;
inline constexpr long kCollapseRoundsPerBodySquared = 8;

// Where pocketed bodies are kept, px: far enough that no distance or box test ever passes.
inline constexpr Vec2 kFarAway{1e30, 1e30};

} // namespace carrom::detail

namespace carrom {

struct ExactEngine::Impl {
    explicit Impl(const PhysicsConfig& c);

    // The board, fixed for the engine's life.
    PhysicsConfig config;
    double k = 0.0;           // damping, 1/s
    double inv_k = 0.0;       // s (infinite when k = 0)
    bool travel_keys = false; // k < kTravelKeyDampingPerS: keys are -S (see kNoEvent)
    std::array<Vec2, 4> pockets{};
    std::array<detail::Box, 4> pocket_boxes{};
    // A path box with x0 > pocket_gap.x0 and x1 < pocket_gap.x1 (or the same in y) lies between
    // the pocket boxes of the left and right (top and bottom) pockets and overlaps none.
    detail::Box pocket_gap{};

    // Per body, in input order.
    std::vector<int> ids;
    std::vector<Vec2> pos;      // px, at `now`; far outside the board once pocketed
    std::vector<Vec2> vel;      // px/s, at `now`
    std::vector<double> speed;  // |vel|, px/s
    std::vector<double> radius; // px
    std::vector<double> inv_mass;
    std::vector<double> lo, hi;    // cushion limits of the centre, px
    double max_radius = 0.0;       // largest radius in the scene, px
    std::vector<char> active;      // not pocketed
    std::vector<char> moving;      // speed above the stop speed
    std::vector<Vec2> pocketed_at; // where a pocketed body entered its pocket, px

    // Broad phase (broad_phase.hpp). Box covering the rest of each body's current path (radius
    // included), px, stored as separate arrays so the broad-phase loop runs without branches.
    std::vector<double> sweep_x0, sweep_y0, sweep_x1, sweep_y1;
    // The same boxes rounded outwards to float (each float box contains the double box), padded
    // to a multiple of 4 with empty boxes, so SSE tests four bodies at a time in box_overlaps.
    std::vector<float> box_x0, box_y0, box_x1, box_y1;
    // near[i] bit j (== near[j] bit i): the path boxes of i and j overlap. predict(i) runs after
    // every change of i's box and updates row and column i, so two bodies can touch only if
    // their bit is set. Used when the scene has at most 64 bodies; larger scenes test every pair.
    std::vector<std::uint64_t> near;
    bool use_near = false;
    // With use_near (at most 64 bodies), bit masks over body indices:
    //   active_mask / moving_mask bit i: active[i] / moving[i];
    //   box_dirty[i]: body i's path box changed since row i of near[] was last computed.
    std::uint64_t active_mask = 0, moving_mask = 0;
    std::vector<char> box_dirty;
    // Without use_near: indices of moving bodies, rebuilt when stale.
    std::vector<int> moving_list;
    bool moving_list_stale = true;
    // Per-instant cache of touch_mask(i): valid when touch_stamp[i] == instant_stamp.
    std::vector<std::uint64_t> touch_bits;
    std::vector<std::uint64_t> touch_stamp;
    std::uint64_t instant_stamp = 0;     // incremented by process_instant; never 0 inside one
    std::vector<std::uint8_t> wall_bits; // bits 0-3: touching the left, right, top, bottom cushion
    void refresh(std::size_t i);
    void update_near(std::size_t i);
    std::uint64_t box_overlaps(std::size_t i) const;
    std::uint64_t touch_mask(std::size_t a);

    // Event prediction and queue (event_queue.cpp, event_queue.hpp).
    std::vector<detail::Prediction> next;
    std::vector<double> keys; // keys[i] == next[i].key, contiguous for the scan for the maximum
    // With use_near: watchers[o] bit j: next[j] is a Pair event naming o.
    std::vector<std::uint64_t> watchers;
    void predict(std::size_t i);
    void set_next(std::size_t i, const detail::Prediction& p);
    std::size_t earliest() const;
    void advance(double key);

    // The current time is u_now = e^(-k now). `now` (s) is derived from it only when an event or
    // segment is recorded or the run ends (now_stale: not yet derived since the last advance).
    // With travel_keys, advance keeps `now` current itself (the sum of the steps' times).
    double now = 0.0;   // s
    double u_now = 1.0; // e^(-k now)
    bool now_stale = false;
    double time_now() {
        if (now_stale) {
            now = -det::log(u_now) * inv_k;
            now_stale = false;
        }
        return now;
    }
    // The key of the time at which the travel factor from now is s (s >= 0).
    double key_after(double s) const { return travel_keys ? -(u_now * s) : u_now * (1.0 - k * s); }
    // Travel factor s at which body i (moving) falls to the stop speed.
    double stop_s(std::size_t i) const { return (1.0 - config.stop_speed_px_s / speed[i]) * inv_k; }

    // One instant's contacts (contact_instant.cpp): scratch reused by every instant.
    std::vector<detail::Contact> contacts;
    std::vector<int> frontier, next_frontier, touched, cluster, root, event_seeds;
    std::vector<char> in_frontier, is_touched, in_cluster;
    std::vector<double> solve_inv_mass; // 0 for bodies pinned by the stop rule at this instant
    detail::ContactSolver solver;
    void process_instant(std::span<const int> seeds);
    bool isolated_pair_round();
    bool isolated_pair(std::size_t a, std::size_t b);
    bool approaching_pair(std::size_t lo_i, std::size_t hi_i, detail::Contact& out) const;
    bool collect_isolated_pair();
    bool collect_lone_body();
    void collect_walls(std::size_t a);
    void collect_impacts_near();
    void collect_impacts_all_pairs();
    void collect_cluster();
    void solve_groups();
    void mark_touched(std::size_t i);
    void clear_touched();
    double restitution(double approach_px_s, bool cushion) const;

    // The run (engine_run.cpp).
    SimOptions options;
    SimResult result;
    void load(std::span<const Body> bodies);
    void settle_initial_state(std::uint64_t unchanged);
    void run_events();
    void finish();
    void emit(EventKind kind, std::size_t a, int b, double impulse);
    void record_segment(std::size_t i);
    void stop_body(std::size_t i);
    void pocket_body(std::size_t i, int pocket);

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

    // The last scene that passed validate_scene (empty after a rejected one); exact_engine.cpp.
    std::vector<Body> validated;
    std::uint64_t unchanged_since_validated(std::span<const Body> bodies) const;
};

// Called for every event from several files; defined here so that each can inline them.

inline void ExactEngine::Impl::emit(EventKind kind, std::size_t a, int b, double impulse) {
    ++result.stats.events;
    if (options.record_events) {
        result.events.push_back({time_now(), kind, ids[a], b, impulse, pos[a]});
    }
}

inline void ExactEngine::Impl::record_segment(std::size_t i) {
    if (options.record_trajectory) {
        result.trajectory.segments.push_back(
            {time_now(), static_cast<int>(i), pos[i], vel[i], active[i] == 0});
    }
}

inline void ExactEngine::Impl::mark_touched(std::size_t i) {
    if (!is_touched[i]) {
        is_touched[i] = 1;
        touched.push_back(static_cast<int>(i));
    }
}

inline void ExactEngine::Impl::clear_touched() {
    for (int t : touched) {
        is_touched[static_cast<std::size_t>(t)] = 0;
    }
    touched.clear();
}

} // namespace carrom
