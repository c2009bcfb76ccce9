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
#include <cmath>

namespace carrom {

using detail::Contact;
using detail::kApproachTolerancePxS;
using detail::kNever;
using detail::kTouchTolerancePx;

namespace {

enum class Next : std::uint8_t { None, Pair, Cushion, Pocket, Stop };

struct Prediction {
    double t_s = kNever;
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
    std::vector<Vec2> pos;       // px, at `now`; far outside the board once pocketed
    std::vector<Vec2> vel;       // px/s, at `now`
    std::vector<double> speed;   // |vel|, px/s
    std::vector<double> radius;  // px
    std::vector<double> inv_mass;
    std::vector<double> lo, hi;  // cushion limits of the centre, px
    double max_radius = 0.0;     // largest radius in the scene, px
    std::vector<char> active;    // not pocketed
    std::vector<char> moving;    // speed above the stop speed
    // Box covering the rest of each body's current path (radius included), px, stored as
    // separate arrays so the broad-phase loop runs without branches.
    std::vector<double> sweep_x0, sweep_y0, sweep_x1, sweep_y1;
    std::vector<Vec2> pocketed_at; // where a pocketed body entered its pocket, px
    std::vector<int> candidates;   // scratch for predict
    std::vector<Prediction> next;

    // Scratch for one instant of simultaneous impacts.
    std::vector<Contact> contacts;
    std::vector<int> frontier, next_frontier, touched, cluster, root, event_seeds;
    std::vector<char> in_frontier, is_touched, in_cluster;
    std::vector<double> solve_inv_mass; // 0 for bodies pinned by the stop rule at this instant
    detail::ContactSolver solver;

    double now = 0.0;
    SimOptions options;
    SimResult result;

    void load(std::span<const Body> bodies);
    void settle_initial_state();
    void run_events();
    void finish();

    double stop_s(std::size_t i) const { return (1.0 - config.stop_speed_px_s / speed[i]) * inv_k; }
    double time_after(double s) const { return s <= 0.0 ? 0.0 : -std::log1p(-k * s) * inv_k; }
    void refresh(std::size_t i);
    void advance(double t_s);
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
    sweep_x0.resize(n);
    sweep_y0.resize(n);
    sweep_x1.resize(n);
    sweep_y1.resize(n);
    pocketed_at.assign(n, Vec2{});
    candidates.resize(n);
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
    moving[i] = active[i] && speed[i] > 0.0;
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

void ExactEngine::Impl::advance(double t_s) {
    const double dt = t_s - now;
    if (dt <= 0.0) {
        return;
    }
    const double s = -std::expm1(-k * dt) * inv_k;
    const double decay = std::exp(-k * dt);
    // Bodies at rest and pocketed bodies have a velocity of exactly zero, so updating every
    // body leaves them bit-for-bit unchanged and keeps the loop free of branches.
    const std::size_t n = pos.size();
    for (std::size_t i = 0; i < n; ++i) {
        pos[i] += vel[i] * s;
        vel[i] *= decay;
        speed[i] *= decay;
    }
    now = t_s;
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
    // Broad phase: bodies whose path boxes overlap body i's, found without branches.
    const std::size_t n = pos.size();
    const double x0 = sweep_x0[i], y0 = sweep_y0[i], x1 = sweep_x1[i], y1 = sweep_y1[i];
    std::size_t count = 0;
    for (std::size_t j = 0; j < n; ++j) {
        candidates[count] = static_cast<int>(j);
        count += static_cast<std::size_t>((x0 <= sweep_x1[j]) & (sweep_x0[j] <= x1) &
                                          (y0 <= sweep_y1[j]) & (sweep_y0[j] <= y1));
    }
    for (std::size_t c = 0; c < count; ++c) {
        const auto j = static_cast<std::size_t>(candidates[c]);
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
    best.t_s = best.kind == Next::None ? kNever : now + time_after(best_s);
    next[i] = best;
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
        const std::size_t count = pos.size();
        for (std::size_t b = 0; b < count; ++b) {
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
    std::vector<int>& seeds = event_seeds;
    while (!next.empty()) {
        std::size_t first = 0;
        for (std::size_t i = 1; i < next.size(); ++i) {
            if (next[i].t_s < next[first].t_s) {
                first = i;
            }
        }
        if (next[first].kind == Next::None) {
            break;
        }
        const Prediction event = next[first];
        if (event.t_s > options.until_s) {
            advance(options.until_s);
            return;
        }
        if (result.stats.events >= config.max_events) {
            result.truncated = true;
            for (std::size_t i = 0; i < pos.size(); ++i) {
                if (moving[i]) {
                    stop_body(i);
                }
            }
            return;
        }
        advance(event.t_s);
        seeds.assign(1, static_cast<int>(first));
        switch (event.kind) {
        case Next::Stop: stop_body(first); break;
        case Next::Pocket: pocket_body(first, event.other); break;
        case Next::Pair:
            seeds.push_back(event.other);
            process_instant(seeds);
            break;
        case Next::Cushion: process_instant(seeds); break;
        case Next::None: break;
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

const PhysicsConfig& ExactEngine::config() const { return impl_->config; }

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
