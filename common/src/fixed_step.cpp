// The seed's frame loop (tech note sections 03-04) as a fixed-step integrator in px and s.
// Used only to measure the exact engine against; see fixed_step.hpp for the step itself.
//
// Invariants and policies:
// - One step of length h moves every unpocketed body p += v h, damps v *= e^(-k h), stops it
//   when |v| <= stop speed (a speed, not per axis), then clamps it into the cushions
//   (reflecting the outward normal velocity times the cushion restitution) and pockets it
//   when its centre is strictly inside a pocket circle.
// - Then every unpocketed pair (i < j in input order) that overlaps gets, if approaching, the
//   impulse J = (1 + e) m_a m_b / (m_a + m_b) v_n, and is pushed apart by overlap / 2 + 0.5 px
//   each side, as the seed does (which may push a body past a cushion until the next step).
// - Time after n full steps is n * dt (no accumulated rounding). A step is shortened only to
//   land exactly on until_s.
// - Invalid options (dt not finite or <= 0) simulate nothing; substeps < 1 count as 1.

#include "carrom/fixed_step.hpp"
#include "carrom/det_math.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace carrom {
namespace {

// The work bound of one run: about a second of pair tests.
constexpr long kMaxFixedStepPairTests = 1L << 26;

struct StepContext {
    const PhysicsConfig& config;
    const FixedStepOptions& options;
    FixedStepResult& result;
    double t_s = 0.0; // time at the end of the current step
};

void record(StepContext& ctx, EventKind kind, const Body& a, int b, double impulse) {
    if (!ctx.options.record_events) {
        return;
    }
    ctx.result.events.push_back(Event{ctx.t_s, kind, a.id, b, impulse, a.pos_px});
}

bool is_moving(const Body& body) {
    return body.vel_px_s.x != 0.0 || body.vel_px_s.y != 0.0;
}

// Clamps one axis into [lo, hi]; reflects the velocity component when it points outward.
// Returns the normal impulse magnitude (mass * px/s), or a negative number when untouched.
double clamp_axis(double& pos, double& vel, double lo, double hi, bool at_low, double mass,
                  double restitution) {
    const bool outside = at_low ? pos < lo : pos > hi;
    if (!outside) {
        return -1.0;
    }
    pos = at_low ? lo : hi;
    const bool outward = at_low ? vel < 0.0 : vel > 0.0;
    if (!outward) {
        return 0.0;
    }
    const double impulse = mass * (1.0 + restitution) * std::abs(vel);
    vel = -vel * restitution;
    return impulse;
}

void apply_cushions(StepContext& ctx, Body& body) {
    const double r = ctx.config.radius(body.kind);
    const double lo = ctx.config.cushion_min(r);
    const double hi = ctx.config.cushion_max(r);
    const double m = ctx.config.mass(body.kind);
    const double e = ctx.config.cushion_restitution;
    const double hits[4] = {
        clamp_axis(body.pos_px.x, body.vel_px_s.x, lo, hi, true, m, e),
        clamp_axis(body.pos_px.x, body.vel_px_s.x, lo, hi, false, m, e),
        clamp_axis(body.pos_px.y, body.vel_px_s.y, lo, hi, true, m, e),
        clamp_axis(body.pos_px.y, body.vel_px_s.y, lo, hi, false, m, e),
    };
    const int cushions[4] = {kCushionLeft, kCushionRight, kCushionTop, kCushionBottom};
    for (int i = 0; i < 4; ++i) {
        if (hits[i] >= 0.0) {
            record(ctx, EventKind::Cushion, body, cushions[i], hits[i]);
        }
    }
}

void apply_pockets(StepContext& ctx, Body& body) {
    const auto centres = ctx.config.pocket_centres();
    const double r2 = ctx.config.pocket_radius_px * ctx.config.pocket_radius_px;
    for (int i = 0; i < 4; ++i) {
        if (length_squared(body.pos_px - centres[static_cast<std::size_t>(i)]) < r2) {
            body.pocketed = true;
            body.vel_px_s = {};
            record(ctx, EventKind::Pocket, body, i, 0.0);
            return;
        }
    }
}

// Like the seed, resting bodies are also clamped and pocket-tested (a push from a collision
// can move them).
void move_body(StepContext& ctx, Body& body, double h, double damping) {
    if (body.pocketed) {
        return;
    }
    if (is_moving(body)) {
        body.pos_px += body.vel_px_s * h;
        body.vel_px_s *= damping;
        if (length(body.vel_px_s) <= ctx.config.stop_speed_px_s) {
            body.vel_px_s = {};
            record(ctx, EventKind::Stop, body, -1, 0.0);
        }
    }
    apply_cushions(ctx, body);
    apply_pockets(ctx, body);
}

// The seed's checkCollision with the impulse written as (1 + e) m_a m_b / (m_a + m_b) v_n.
void collide_pair(StepContext& ctx, Body& a, Body& b) {
    const Vec2 d = b.pos_px - a.pos_px;
    const double dist = length(d);
    const double min_dist = ctx.config.radius(a.kind) + ctx.config.radius(b.kind);
    if (dist >= min_dist || dist == 0.0) {
        return;
    }
    const Vec2 n = d * (1.0 / dist);
    const double v_n = dot(a.vel_px_s - b.vel_px_s, n);
    if (v_n > 0.0) {
        const double ma = ctx.config.mass(a.kind);
        const double mb = ctx.config.mass(b.kind);
        const double impulse = (1.0 + ctx.config.disc_restitution) * ma * mb / (ma + mb) * v_n;
        a.vel_px_s -= n * (impulse / ma);
        b.vel_px_s += n * (impulse / mb);
        record(ctx, EventKind::Collision, a, b.id, impulse);
    }
    const Vec2 push = n * ((min_dist - dist) / 2.0 + 0.5);
    a.pos_px -= push;
    b.pos_px += push;
}

void collide_all(StepContext& ctx, std::vector<Body>& bodies) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].pocketed) {
            continue;
        }
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            if (!bodies[j].pocketed) {
                collide_pair(ctx, bodies[i], bodies[j]);
            }
        }
    }
}

bool any_moving(const std::vector<Body>& bodies) {
    return std::any_of(bodies.begin(), bodies.end(),
                       [](const Body& b) { return !b.pocketed && is_moving(b); });
}

} // namespace

FixedStepResult simulate_fixed_step(const PhysicsConfig& config, std::span<const Body> bodies,
                                    const FixedStepOptions& options) {
    FixedStepResult result;
    result.bodies.assign(bodies.begin(), bodies.end());
    const int substeps = std::max(options.substeps, 1);
    const double dt = options.frame_dt_s / substeps;
    if (!std::isfinite(dt) || dt <= 0.0) {
        return result;
    }
    const double horizon = std::min(options.until_s, options.max_time_s);
    StepContext ctx{config, options, result};
    // The work bound: every step tests every pair, so the steps are limited to keep the pair
    // tests of one run within kMaxFixedStepPairTests.
    const auto n = static_cast<long>(bodies.size());
    const long max_steps = std::max(kMaxFixedStepPairTests / std::max(n * (n - 1) / 2, 1L), 1L);
    const double k = config.damping_per_s;
    const double full_damping = det::exp(-k * dt);
    while (any_moving(result.bodies) && ctx.t_s < horizon) {
        if (result.steps >= max_steps) {
            result.truncated = true;
            break;
        }
        const double next = static_cast<double>(result.steps + 1) * dt;
        // Land exactly on the horizon instead of overshooting it (within a rounding slack).
        const bool last = next >= horizon - 1e-9 * dt;
        const double h = last ? horizon - ctx.t_s : dt;
        const double damping = last ? det::exp(-k * h) : full_damping;
        ctx.t_s = last ? horizon : next;
        ++result.steps;
        for (Body& body : result.bodies) {
            move_body(ctx, body, h, damping);
        }
        collide_all(ctx, result.bodies);
    }
    result.end_time_s = ctx.t_s;
    return result;
}

} // namespace carrom
