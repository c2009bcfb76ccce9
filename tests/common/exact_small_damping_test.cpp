// Small and zero damping rates: positions, event times and collisions against the closed form
// p(t) = p0 + v0 S(t), S(t) = (1 - e^(-k t)) / k (S = t at k = 0), to well below 1e-9 px.

#include "common/physics_test_util.hpp"

#include <cmath>

namespace carrom {
namespace {

using test::coin;

// The travel factor S(t), s, computed independently of the engine.
double closed_form_travel(double k, double t) {
    return k == 0.0 ? t : -std::expm1(-k * t) / k;
}

// The time at which the travel factor reaches S, s.
double closed_form_time(double k, double s) {
    return k == 0.0 ? s : -std::log1p(-k * s) / k;
}

constexpr double kDampings[] = {0.0, 1e-300, 1e-16, 1e-12, 1e-6, 1e-3, 0.05, 0.2};

PhysicsConfig with_damping(double k) {
    PhysicsConfig config;
    config.damping_per_s = k;
    return config;
}

TEST(ExactSmallDamping, FreeMotionFollowsTheClosedForm) {
    for (double k : kDampings) {
        const PhysicsConfig config = with_damping(k);
        SimOptions options;
        options.until_s = 0.5;
        const std::vector<Body> scene{coin(1, 100.0, 300.0, 400.0, 30.0)};
        const SimulateResult run = simulate_exact(config, scene, options);
        ASSERT_FALSE(run.error) << "k = " << k;
        const Body& b = run.result.bodies[0];
        const double s = closed_form_travel(k, 0.5);
        EXPECT_NEAR(b.pos_px.x, 100.0 + 400.0 * s, 1e-10) << "k = " << k;
        EXPECT_NEAR(b.pos_px.y, 300.0 + 30.0 * s, 1e-10) << "k = " << k;
        EXPECT_NEAR(b.vel_px_s.x, 400.0 * std::exp(-k * 0.5), 1e-10) << "k = " << k;
        EXPECT_EQ(run.result.end_time_s, 0.5) << "k = " << k;
    }
}

TEST(ExactSmallDamping, CushionContactComesAtTheClosedFormTime) {
    for (double k : kDampings) {
        const PhysicsConfig config = with_damping(k);
        const double hi = config.cushion_max(config.coin_radius_px);
        SimOptions options;
        options.until_s = 0.6;
        const std::vector<Body> scene{coin(1, 300.0, 300.0, 500.0, 0.0)};
        const SimulateResult run = simulate_exact(config, scene, options);
        ASSERT_FALSE(run.error);
        ASSERT_FALSE(run.result.events.empty()) << "k = " << k;
        const Event& hit = run.result.events.front();
        EXPECT_EQ(hit.kind, EventKind::Cushion) << "k = " << k;
        const double t_hit = closed_form_time(k, (hi - 300.0) / 500.0);
        EXPECT_NEAR(hit.t_s, t_hit, 1e-14) << "k = " << k;
        EXPECT_NEAR(hit.pos_px.x, hi, 1e-10) << "k = " << k;
    }
}

// Equal masses, e = 1: the striking coin stops dead (and is stopped by the stop rule) and the
// struck coin leaves with the striking coin's speed at contact.
TEST(ExactSmallDamping, HeadOnElasticContactIsExact) {
    for (double k : kDampings) {
        PhysicsConfig config = with_damping(k);
        config.disc_restitution = 1.0;
        SimOptions options;
        options.until_s = 1.0;
        const std::vector<Body> scene{coin(1, 200.0, 300.0, 300.0, 0.0), coin(2, 400.0, 300.0)};
        const SimulateResult run = simulate_exact(config, scene, options);
        ASSERT_FALSE(run.error);
        const double reach = 2.0 * config.coin_radius_px;
        const double t_hit = closed_form_time(k, (200.0 - reach) / 300.0);
        ASSERT_FALSE(run.result.events.empty());
        EXPECT_NEAR(run.result.events.front().t_s, t_hit, 1e-14) << "k = " << k;
        const Body& struck = run.result.bodies[1];
        const double v_hit = 300.0 * std::exp(-k * t_hit);
        const double x = 400.0 + v_hit * closed_form_travel(k, 1.0 - t_hit);
        EXPECT_NEAR(struck.pos_px.x, x, 1e-9) << "k = " << k;
        EXPECT_NEAR(run.result.bodies[0].pos_px.x, 400.0 - reach, 1e-9) << "k = " << k;
        EXPECT_EQ(length(run.result.bodies[0].vel_px_s), 0.0) << "k = " << k;
    }
}

// Without damping and with elastic cushions a coin never stops: the run ends at max_events,
// flagged truncated, with the coin stopped in place inside the cushions (it bounces between
// the left and right cushions, away from the pockets).
TEST(ExactSmallDamping, FrictionlessBouncingEndsAtTheEventBound) {
    PhysicsConfig config = with_damping(0.0);
    config.cushion_restitution = 1.0;
    config.max_events = 100000;
    const std::vector<Body> scene{coin(1, 300.0, 300.0, 700.0, 0.0)};
    const SimulateResult run = simulate_exact(config, scene);
    ASSERT_FALSE(run.error);
    EXPECT_TRUE(run.result.truncated);
    EXPECT_EQ(run.result.stats.events, 100000 + 1); // the bound, then the stop in place
    // Every crossing of the 502 px between the cushion limits takes 502 / 700 s, however long
    // the run has lasted (here about 20 hours of simulated time): each to within the touch
    // tolerance (1e-9 px, 1.4e-12 s at 700 px/s), rather than to the resolution of the time
    // since the start.
    const double crossings = (251.0 + 99999.0 * 502.0) / 700.0;
    EXPECT_NEAR(run.result.end_time_s, crossings, 1e5 * 1.5e-12);
    EXPECT_LT(test::max_cushion_violation(config, run.result.bodies), 1e-12);
}

// A break with no damping and elastic contacts: the invariants hold at every event, and the
// run is bounded.
TEST(ExactSmallDamping, FrictionlessBreakKeepsTheInvariants) {
    PhysicsConfig config = with_damping(0.0);
    config.cushion_restitution = 1.0;
    config.disc_restitution = 1.0;
    config.max_events = 3000;
    std::vector<Body> scene = standard_layout(config);
    scene.push_back(test::striker(kStrikerId, 300.0, 520.0, 80.0, -1500.0));
    const SimulateResult run = simulate_exact(config, scene);
    ASSERT_FALSE(run.error);
    EXPECT_LE(test::kinetic_energy(config, run.result.bodies),
              test::kinetic_energy(config, scene) * (1.0 + 1e-12));
    EXPECT_LT(test::max_overlap(config, run.result.bodies), 1e-6);
    EXPECT_LT(test::max_cushion_violation(config, run.result.bodies), 1e-6);
    double last = 0.0;
    for (const Event& e : run.result.events) {
        ASSERT_TRUE(std::isfinite(e.t_s));
        ASSERT_GE(e.t_s, last);
        last = e.t_s;
    }
}

} // namespace
} // namespace carrom
