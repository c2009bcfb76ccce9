// The contacts of one instant and their solve (process_instant). At one instant no body moves;
// starting from the bodies of an event, rounds of simultaneous impacts are solved until no
// touching contact approaches, then the stop rule pins the bodies left below the stop speed.
//
// The contact order. Every collector below produces, for the same frontier, exactly the same
// contacts in the same order, and the results (the pinned hashes) depend on that order:
//   for each frontier body a in frontier order, skipping pocketed ones:
//     its approaching contacts {a, b} with every active body b it touches (gap <=
//     kTouchTolerancePx), b in increasing index; a pair of two frontier bodies is taken only
//     from its lower index, and a pair of two pinned bodies (solve_inv_mass 0) not at all;
//     then its approaching cushion contacts: left, right, top, bottom.
// A contact "approaches" when its normal relative speed is below -kApproachTolerancePxS.
// collect_impacts_all_pairs is that definition over all bodies; collect_impacts_near takes the
// touching bodies from touch_mask (use_near); collect_lone_body and collect_isolated_pair are
// its two common cases without the loops.

#include "broad_phase.hpp"
#include "contact_time.hpp"
#include "engine_state.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace carrom {

using detail::Contact;
using detail::kApproachTolerancePxS;
using detail::kCollapseRoundsPerBodySquared;
using detail::kRoundsBeforeCollapse;
using detail::kTouchTolerancePx;

namespace {

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

// Resolves everything that happens at `now`, starting from the seed bodies: rounds of
// simultaneous impacts until no touching contact approaches; then the stop rule for bodies left
// below the stop speed (they are pinned for the rest of the instant, and bodies still pushing
// into them are resolved against them). Bounded: each round either ends the cascade, or after
// max(kRoundsBeforeCollapse, kCollapseRoundsPerBodySquared m^2) rounds (m the bodies reached)
// the cluster is solved plastically; each stop pass pins at least one more body.
void ExactEngine::Impl::process_instant(std::span<const int> seeds) {
    ++instant_stamp;
    clear_touched();
    frontier.assign(seeds.begin(), seeds.end());
    for (int s : seeds) {
        mark_touched(static_cast<std::size_t>(s));
    }
    long rounds = use_near && seeds.size() == 2 && isolated_pair_round() ? 1 : 0;
    const double stop2 = config.stop_speed_px_s * config.stop_speed_px_s;
    const auto bodies = static_cast<long>(pos.size()) + 1;
    const long max_rounds =
        (kRoundsBeforeCollapse + 2) * bodies + kCollapseRoundsPerBodySquared * bodies * bodies;
    while (!frontier.empty() && rounds < max_rounds) {
        if (!use_near) {
            collect_impacts_all_pairs();
        } else if (!(frontier.size() == 2 && collect_isolated_pair()) &&
                   !(frontier.size() == 1 && collect_lone_body())) {
            collect_impacts_near();
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

double ExactEngine::Impl::restitution(double approach_px_s, bool cushion) const {
    if (approach_px_s < config.restitution_floor_px_s) {
        return 0.0;
    }
    return cushion ? config.cushion_restitution : config.disc_restitution;
}

// The contacts in the contact order (see the top of this file), with use_near: the touching
// bodies from the per-instant touch masks, the touching cushions from the wall bits.
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
// cushion contacts only (the contact order, without the loops). Returns false, collecting
// nothing, otherwise.
bool ExactEngine::Impl::collect_lone_body() {
    const auto a = static_cast<std::size_t>(frontier[0]);
    if (!active[a] || (touch_mask(a) & active_mask) != 0) {
        return false;
    }
    contacts.clear();
    collect_walls(a);
    return true;
}

// The contacts in the contact order (see the top of this file), without use_near: every body is
// tested for touching.
void ExactEngine::Impl::collect_impacts_all_pairs() {
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
        for (std::size_t b = 0; b < pos.size(); ++b) {
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

// The first round of process_instant for a pair event (frontier: the two seeds) when the two
// bodies touch each other and nothing else: collect_isolated_pair's contact, then the solve and
// bookkeeping of the general round (solve_groups with one contact; the contact's bodies not
// pinned, lower index first, form the next frontier), without its loops. Returns false when the
// pair is not isolated or does not approach; the general round then runs and finds the same.
bool ExactEngine::Impl::isolated_pair_round() {
    if (!collect_isolated_pair() || contacts.empty()) {
        return false;
    }
    ++result.stats.contact_rounds;
    solver.resolve(contacts, vel, solve_inv_mass);
    frontier.clear();
    const Contact& c = contacts.front();
    if (c.impulse > 0.0) {
        const auto lo_i = static_cast<std::size_t>(c.a);
        const auto hi_i = static_cast<std::size_t>(c.b);
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

// collect_impacts_near for a frontier of two bodies that form an isolated pair: the contact
// order without the loops (none, or the pair's, visited from its lower index). Returns false, and
// collects nothing, when the frontier is not such a pair.
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
// approach (normal relative speed below -kApproachTolerancePxS); false otherwise.
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

} // namespace carrom
