// The exact event-driven engine. Invariants between events:
//   - pos/vel of every body are exact (to rounding) at time `now`;
//   - next[i] holds the earliest event of body i that is still valid: its own stop, cushion or
//     pocket, or its first contact with another body given both current trajectories. When a
//     body's trajectory changes, it and every body whose prediction names it are recomputed;
//     the global next event is the minimum over next[] (see docs/physics.md, "Event queue").
//   - bodies at rest have no events of their own; a pair with both bodies at rest is never solved.

#include "carrom/exact_engine.hpp"

#include "contact_solver.hpp"
#include "contact_time.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
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
// travel factor s has u = u_now (1 - k s), with no logarithm. The earliest event has the
// largest key; kNoEvent is below every real key (real keys are > 0).
constexpr double kNoEvent = -1.0;

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
// contact group (the remedy for zero-time inelastic collapse; docs/physics.md).
constexpr int kRoundsBeforeCollapse = 16;

// Where pocketed bodies are kept, px: far enough that no distance or box test ever passes.
constexpr Vec2 kFarAway{1e30, 1e30};

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
    double k = 0.0;     // damping, 1/s
    double inv_k = 0.0; // s
    std::array<Vec2, 4> pockets{};
    std::array<Box, 4> pocket_boxes{};

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
    std::vector<Vec2> pocketed_at; // where a pocketed body entered its pocket, px
    // near[i] bit j (== near[j] bit i): the path boxes of i and j overlap. predict(i) runs after
    // every change of i's box and updates row and column i, so two bodies can touch only if
    // their bit is set. Used when the scene has at most 64 bodies; larger scenes test every pair.
    std::vector<std::uint64_t> near;
    bool use_near = false;
    std::uint64_t box_overlaps(std::size_t i) const;

    std::vector<Prediction> next;
    std::vector<int> moving_list; // indices of moving bodies, rebuilt when stale
    bool moving_list_stale = true;

    // Scratch for one instant of simultaneous impacts.
    std::vector<Contact> contacts;
    std::vector<int> frontier, next_frontier, touched, cluster, root, event_seeds;
    std::vector<char> in_frontier, is_touched, in_cluster;
    std::vector<double> solve_inv_mass; // 0 for bodies pinned by the stop rule at this instant
    detail::ContactSolver solver;

    double now = 0.0;   // s
    double u_now = 1.0; // e^(-k now)
    SimOptions options;
    SimResult result;

    void load(std::span<const Body> bodies);
    void settle_initial_state();
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
    pockets = c.pocket_centres();
    for (std::size_t p = 0; p < pockets.size(); ++p) {
        const double r = c.pocket_radius_px;
        pocket_boxes[p] = {pockets[p].x - r, pockets[p].y - r, pockets[p].x + r, pockets[p].y + r};
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
    pocketed_at.assign(n, Vec2{});
    near.assign(n, 0);
    moving_list_stale = true;
    use_near = n <= 64;
    next.assign(n, Prediction{});
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
    max_radius = 0.0;
    for (double r : radius) {
        max_radius = std::max(max_radius, r);
    }
    now = 0.0;
    u_now = 1.0;
    result.bodies.assign(bodies.begin(), bodies.end());
    result.events.clear();
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
    speed[i] = length(vel[i]);
    const char now_moving = active[i] && speed[i] > 0.0;
    moving_list_stale = moving_list_stale || now_moving != moving[i];
    moving[i] = now_moving;
    const double r = radius[i];
    Vec2 end = pos[i];
    if (moving[i]) {
        end += vel[i] * stop_s(i);
    }
    sweep_x0[i] = std::min(pos[i].x, end.x) - r;
    sweep_y0[i] = std::min(pos[i].y, end.y) - r;
    sweep_x1[i] = std::max(pos[i].x, end.x) + r;
    sweep_y1[i] = std::max(pos[i].y, end.y) + r;
}

void ExactEngine::Impl::emit(EventKind kind, std::size_t a, int b, double impulse) {
    ++result.stats.events;
    if (options.record_events) {
        result.events.push_back({now, kind, ids[a], b, impulse, pos[a]});
    }
}

void ExactEngine::Impl::record_segment(std::size_t i) {
    if (options.record_trajectory) {
        result.trajectory.segments.push_back(
            {now, static_cast<int>(i), pos[i], vel[i], active[i] == 0});
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
    record_segment(i);
    pocketed_at[i] = pos[i];
    pos[i] = kFarAway;
    refresh(i);
}

// Moves every body to the time whose key is u (u <= u_now).
void ExactEngine::Impl::advance(double u) {
    if (u >= u_now) {
        return;
    }
    const double decay = u / u_now;         // e^(-k dt)
    const double s = (1.0 - decay) * inv_k; // (1 - e^(-k dt)) / k
    const std::size_t n = pos.size();
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
        const auto i = static_cast<std::size_t>(mi);
        pos[i] += vel[i] * s;
        vel[i] *= decay;
        speed[i] *= decay;
    }
    u_now = u;
    now = -std::log(u) * inv_k;
}

void ExactEngine::Impl::predict(std::size_t i) {
    Prediction best;
    double best_s = kNever;
    if (!active[i]) {
        next[i] = best;
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
        for (std::size_t p = 0; p < pockets.size(); ++p) {
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
    std::uint64_t row = 0;
    if (use_near) {
        row = box_overlaps(i) & ~(std::uint64_t{1} << i);
        // Keep near symmetric: flip bit i of every body whose bit in row i changed.
        for (std::uint64_t diff = row ^ near[i]; diff != 0; diff &= diff - 1) {
            near[static_cast<std::size_t>(std::countr_zero(diff))] ^= std::uint64_t{1} << i;
        }
        near[i] = row;
    }
    for (std::size_t scan = 0; scan < (use_near ? std::size_t{64} : n); ++scan) {
        std::size_t j = scan;
        if (use_near) {
            if (row == 0) {
                break;
            }
            j = static_cast<std::size_t>(std::countr_zero(row));
            row &= row - 1;
        } else if (!(sweep_x0[i] <= sweep_x1[j] && sweep_x0[j] <= sweep_x1[i] &&
                     sweep_y0[i] <= sweep_y1[j] && sweep_y0[j] <= sweep_y1[i])) {
            continue;
        }
        if (j == i || !active[j] || (!moving[i] && !moving[j])) {
            continue;
        }
        ++result.stats.pair_tests;
        const double s =
            detail::time_to_reach(pos[j] - pos[i], vel[j] - vel[i], radius[i] + radius[j], best_s);
        // The contact counts only if it comes before body j stops.
        if (s < best_s && (!moving[j] || s < stop_s(j))) {
            best_s = s;
            best = {0.0, Next::Pair, static_cast<int>(j)};
        }
    }
    best.key = best.kind == Next::None ? kNoEvent : u_now * (1.0 - k * best_s);
    next[i] = best;
}

// Bit j set: the path boxes of i and j overlap (i itself included). n <= 64. The box arrays
// are padded to an even length with empty boxes, so SSE2 can test two bodies at a time.
std::uint64_t ExactEngine::Impl::box_overlaps(std::size_t i) const {
    const double* bx0 = sweep_x0.data();
    const double* by0 = sweep_y0.data();
    const double* bx1 = sweep_x1.data();
    const double* by1 = sweep_y1.data();
    std::uint64_t row = 0;
    const std::size_t n = sweep_x0.size();
#if defined(__SSE2__)
    const __m128d x0 = _mm_set1_pd(bx0[i]);
    const __m128d y0 = _mm_set1_pd(by0[i]);
    const __m128d x1 = _mm_set1_pd(bx1[i]);
    const __m128d y1 = _mm_set1_pd(by1[i]);
    for (std::size_t j = 0; j < n; j += 2) {
        const __m128d hit_x = _mm_and_pd(_mm_cmple_pd(x0, _mm_loadu_pd(bx1 + j)),
                                         _mm_cmple_pd(_mm_loadu_pd(bx0 + j), x1));
        const __m128d hit_y = _mm_and_pd(_mm_cmple_pd(y0, _mm_loadu_pd(by1 + j)),
                                         _mm_cmple_pd(_mm_loadu_pd(by0 + j), y1));
        const auto bits = static_cast<std::uint64_t>(_mm_movemask_pd(_mm_and_pd(hit_x, hit_y)));
        row |= bits << j;
    }
#else
    const double x0 = bx0[i], y0 = by0[i], x1 = bx1[i], y1 = by1[i];
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

// Impacts at `now`: touching, approaching contacts that involve a body of the frontier.
void ExactEngine::Impl::collect_impacts() {
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
        const std::uint64_t near_a = use_near ? near[a] : 0;
        const std::size_t count =
            use_near ? static_cast<std::size_t>(std::popcount(near_a)) : pos.size();
        std::uint64_t bits = near_a;
        for (std::size_t scan = 0; scan < count; ++scan) {
            std::size_t b = scan;
            if (use_near) {
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
    for (const Contact& c : contacts) {
        root[static_cast<std::size_t>(c.a)] = c.a;
        if (c.b >= 0) {
            root[static_cast<std::size_t>(c.b)] = c.b;
        }
    }
    if (contacts.size() == 1) {
        solver.resolve(contacts, vel, solve_inv_mass);
        return;
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
// kRoundsBeforeCollapse rounds the cluster is solved plastically; each stop pass pins at least
// one more body.
void ExactEngine::Impl::process_instant(std::span<const int> seeds) {
    clear_touched();
    frontier.assign(seeds.begin(), seeds.end());
    for (int s : seeds) {
        mark_touched(static_cast<std::size_t>(s));
    }
    int rounds = 0;
    const double stop2 = config.stop_speed_px_s * config.stop_speed_px_s;
    const int max_rounds = (kRoundsBeforeCollapse + 2) * (static_cast<int>(pos.size()) + 1);
    while (!frontier.empty() && rounds < max_rounds) {
        collect_impacts();
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
        if (rounds > kRoundsBeforeCollapse) {
            collect_cluster();
            ++result.stats.collapse_solves;
        }
        solve_groups();
        next_frontier.clear();
        for (const Contact& c : contacts) {
            if (c.impulse <= 0.0) {
                continue;
            }
            const auto a = static_cast<std::size_t>(c.a);
            if (c.b >= 0) {
                emit(EventKind::Collision, a, ids[static_cast<std::size_t>(c.b)], c.impulse);
            } else {
                emit(EventKind::Cushion, a, cushion_index(c.normal), c.impulse);
            }
            for (int body : {c.a, c.b}) {
                if (body >= 0 && solve_inv_mass[static_cast<std::size_t>(body)] != 0.0 &&
                    std::find(next_frontier.begin(), next_frontier.end(), body) ==
                        next_frontier.end()) {
                    next_frontier.push_back(body);
                    mark_touched(static_cast<std::size_t>(body));
                }
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

void ExactEngine::Impl::clear_touched() {
    for (int t : touched) {
        is_touched[static_cast<std::size_t>(t)] = 0;
    }
    touched.clear();
}

void ExactEngine::Impl::settle_initial_state() {
    for (std::size_t i = 0; i < pos.size(); ++i) {
        if (!active[i]) {
            continue;
        }
        for (std::size_t p = 0; p < pockets.size(); ++p) {
            if (length(pos[i] - pockets[p]) < config.pocket_radius_px) {
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
    std::vector<int> seeds;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        if (moving[i]) {
            seeds.push_back(static_cast<int>(i));
        }
    }
    if (!seeds.empty()) {
        process_instant(seeds);
        clear_touched();
    }
    for (std::size_t i = 0; i < pos.size(); ++i) {
        predict(i);
    }
}

void ExactEngine::Impl::run_events() {
    const double u_until = std::exp(-k * options.until_s); // 0 when there is no end time
    std::vector<int>& seeds = event_seeds;
    long pops = 0;
    while (!next.empty()) {
        std::size_t first = 0;
        for (std::size_t i = 1; i < next.size(); ++i) {
            if (next[i].key > next[first].key) {
                first = i;
            }
        }
        if (next[first].kind == Next::None) {
            break;
        }
        const Prediction event = next[first];
        if (event.key < u_until) {
            advance(u_until);
            now = options.until_s; // exact, rather than recomputed from the key
            return;
        }
        // Every pop normally emits at least one event; the pop count guards the bound even if
        // rounding ever made a predicted event a no-op.
        ++pops;
        if (result.stats.events >= config.max_events || pops > 4L * config.max_events) {
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
    result.end_time_s = now;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        Body& b = result.bodies[i];
        b.pos_px = active[i] ? pos[i] : pocketed_at[i];
        b.vel_px_s = vel[i];
        b.pocketed = active[i] == 0;
    }
}

ExactEngine::ExactEngine(const PhysicsConfig& config) : impl_(std::make_unique<Impl>(config)) {}
ExactEngine::~ExactEngine() = default;

const PhysicsConfig& ExactEngine::config() const {
    return impl_->config;
}

ExactEngine::Outcome ExactEngine::run(std::span<const Body> bodies, const SimOptions& options) {
    if (auto error = validate_scene(impl_->config, bodies)) {
        return {std::move(error), nullptr};
    }
    impl_->options = options;
    impl_->load(bodies);
    impl_->settle_initial_state();
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
