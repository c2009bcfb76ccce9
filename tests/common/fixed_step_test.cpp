// The fixed-step integrator (the seed's frame loop in px and s): exact discrete answers where
// they exist, convergence to the closed form as dt -> 0, and the seed's contact rules.

#include "carrom/fixed_step.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace carrom {
namespace {

Body coin(int id, Vec2 pos, Vec2 vel = {}) {
    return Body{id, BodyKind::Black, pos, vel, false};
}
Body striker(int id, Vec2 pos, Vec2 vel = {}) {
    return Body{id, BodyKind::Striker, pos, vel, false};
}

FixedStepOptions options_with(double dt, double until_s = 1e300) {
    FixedStepOptions options;
    options.frame_dt_s = dt;
    options.until_s = until_s;
    return options;
}

std::vector<Event> events_of(const FixedStepResult& result, EventKind kind) {
    std::vector<Event> out;
    std::copy_if(result.events.begin(), result.events.end(), std::back_inserter(out),
                 [kind](const Event& e) { return e.kind == kind; });
    return out;
}

// Closed form of damped free motion: p(t) = p0 + v0 (1 - e^(-k t)) / k.
double slide_x(const PhysicsConfig& c, double x0, double v0, double t) {
    return x0 + v0 * (1.0 - std::exp(-c.damping_per_s * t)) / c.damping_per_s;
}

TEST(FixedStep, FreeSlideMatchesTheDiscreteSum) {
    // n steps of p += v h; v *= d travel v0 h (1 - d^n) / (1 - d).
    const PhysicsConfig c;
    const std::vector<Body> bodies{coin(0, {100, 300}, {300, 0})};
    const double h = 1.0 / 60.0;
    const auto result = simulate_fixed_step(c, bodies, options_with(h, 0.5));
    const double d = std::exp(-c.damping_per_s * h);
    const double expected = 100.0 + 300.0 * h * (1.0 - std::pow(d, 30)) / (1.0 - d);
    EXPECT_EQ(result.steps, 30);
    EXPECT_DOUBLE_EQ(result.end_time_s, 0.5);
    EXPECT_NEAR(result.bodies[0].pos_px.x, expected, 1e-9);
    EXPECT_EQ(result.bodies[0].pos_px.y, 300.0);
    EXPECT_NEAR(result.bodies[0].vel_px_s.x, 300.0 * std::pow(d, 30), 1e-9);
}

TEST(FixedStep, FreeSlideErrorShrinksLinearlyWithDt) {
    const PhysicsConfig c;
    const std::vector<Body> bodies{coin(0, {100, 300}, {400, 0})};
    const double exact = slide_x(c, 100.0, 400.0, 0.5);
    double previous_error = 0.0;
    for (int substeps : {1, 2, 4, 8, 16, 32}) {
        FixedStepOptions options = options_with(1.0 / 60.0, 0.5);
        options.substeps = substeps;
        const auto result = simulate_fixed_step(c, bodies, options);
        const double error = std::abs(result.bodies[0].pos_px.x - exact);
        EXPECT_GT(error, 0.0);
        if (previous_error > 0.0) {
            // First order: halving dt halves the error.
            EXPECT_NEAR(error / previous_error, 0.5, 0.01) << "substeps " << substeps;
        }
        previous_error = error;
    }
    // Leading term of the error: v0 (1 - e^(-k t)) dt / 2.
    const double h = 1.0 / 60.0 / 32.0;
    const double leading = 400.0 * (1.0 - std::exp(-c.damping_per_s * 0.5)) * h / 2.0;
    EXPECT_NEAR(previous_error / leading, 1.0, 0.01);
}

TEST(FixedStep, SubstepsEqualASmallerFrame) {
    const PhysicsConfig c;
    const std::vector<Body> bodies{striker(19, {300, 520}, {30, -1500}), coin(0, {300, 300}),
                                   coin(1, {300, 265})};
    FixedStepOptions split = options_with(1.0 / 60.0);
    split.substeps = 16;
    const auto a = simulate_fixed_step(c, bodies, split);
    const auto b = simulate_fixed_step(c, bodies, options_with(1.0 / 960.0));
    ASSERT_EQ(a.steps, b.steps);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        EXPECT_EQ(a.bodies[i].pos_px, b.bodies[i].pos_px);
    }
}

TEST(FixedStep, StopsWhenSpeedFallsToTheStopSpeed) {
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {300, 300}, {5.0 / 0.99, 3.0 / 0.99})};
    const double h = 1.0 / 60.0;
    const auto result = simulate_fixed_step(c, one, options_with(h));
    EXPECT_EQ(result.steps, 1);
    const auto stops = events_of(result, EventKind::Stop);
    ASSERT_EQ(stops.size(), 1u);
    EXPECT_EQ(stops[0].a, 0);
    EXPECT_DOUBLE_EQ(stops[0].t_s, h);
    EXPECT_EQ(result.bodies[0].vel_px_s, Vec2{});
}

TEST(FixedStep, StopSpeedIsASpeedNotAPerAxisBound) {
    // 5.5 px/s on each axis is below the stop speed per axis but 7.8 px/s as a speed.
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {300, 300}, {5.5, 5.5})};
    const double h = 1.0 / 60.0;
    const auto result = simulate_fixed_step(c, one, options_with(h));
    const double speed = std::sqrt(2.0) * 5.5;
    EXPECT_EQ(static_cast<double>(result.steps),
              std::ceil(std::log(speed / c.stop_speed_px_s) / (c.damping_per_s * h)));
    EXPECT_GT(result.steps, 10);
}

TEST(FixedStep, StopTimeFollowsTheDampingRate) {
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {300, 300}, {0, 60})};
    const double h = 1.0 / 600.0;
    const auto result = simulate_fixed_step(c, one, options_with(h));
    // Speed 60 e^(-k n h) reaches 6 at n = ln(10) / (k h).
    const double n = std::ceil(std::log(10.0) / (c.damping_per_s * h));
    EXPECT_EQ(static_cast<double>(result.steps), n);
    EXPECT_DOUBLE_EQ(result.end_time_s, n * h);
}

TEST(FixedStep, RestingSceneTakesNoStep) {
    const PhysicsConfig c;
    const std::vector<Body> bodies{coin(0, {300, 300}), coin(1, {100, 100})};
    const auto result = simulate_fixed_step(c, bodies, options_with(1.0 / 60.0));
    EXPECT_EQ(result.steps, 0);
    EXPECT_EQ(result.end_time_s, 0.0);
    EXPECT_TRUE(result.events.empty());
}

TEST(FixedStep, CushionClampsAndReflectsTheNormalComponent) {
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {60, 300}, {-600, 120})};
    const double h = 1.0 / 60.0;
    const auto full = simulate_fixed_step(c, one, options_with(h, 0.2));
    const auto cushions = events_of(full, EventKind::Cushion);
    ASSERT_EQ(cushions.size(), 1u);
    EXPECT_EQ(cushions[0].a, 0);
    EXPECT_EQ(cushions[0].b, kCushionLeft);
    EXPECT_EQ(cushions[0].pos_px.x, c.cushion_min(c.coin_radius_px));
    // Step 1 moves 10 px to x = 50; step 2 crosses x = 49.
    EXPECT_DOUBLE_EQ(cushions[0].t_s, 2 * h);

    const auto at_hit = simulate_fixed_step(c, one, options_with(h, 2 * h));
    const double d = std::exp(-c.damping_per_s * h);
    const double vx_before = -600.0 * d * d;
    EXPECT_DOUBLE_EQ(at_hit.bodies[0].vel_px_s.x, -0.8 * vx_before);
    EXPECT_DOUBLE_EQ(at_hit.bodies[0].vel_px_s.y, 120.0 * d * d);
    EXPECT_DOUBLE_EQ(cushions[0].impulse, 1.8 * std::abs(vx_before));
}

TEST(FixedStep, CushionIndicesFollowTheEventConvention) {
    const PhysicsConfig c;
    const double lo = c.cushion_min(c.coin_radius_px);
    const double hi = c.cushion_max(c.coin_radius_px);
    struct Case {
        Vec2 pos, vel;
        int cushion;
    };
    for (const Case& k :
         {Case{{lo + 1, 300}, {-300, 0}, kCushionLeft},
          Case{{hi - 1, 300}, {300, 0}, kCushionRight}, Case{{300, lo + 1}, {0, -300}, kCushionTop},
          Case{{300, hi - 1}, {0, 300}, kCushionBottom}}) {
        const std::vector<Body> one{coin(0, k.pos, k.vel)};
        const auto result = simulate_fixed_step(c, one, options_with(1.0 / 60.0, 0.05));
        const auto cushions = events_of(result, EventKind::Cushion);
        ASSERT_EQ(cushions.size(), 1u);
        EXPECT_EQ(cushions[0].b, k.cushion);
    }
}

TEST(FixedStep, PocketsABodyWhoseCentreEntersAPocket) {
    const PhysicsConfig c;
    const std::vector<Body> bodies{coin(3, {540, 200}, {0, 600}), coin(4, {300, 300})};
    const auto result = simulate_fixed_step(c, bodies, options_with(1.0 / 60.0));
    const auto pockets = events_of(result, EventKind::Pocket);
    ASSERT_EQ(pockets.size(), 1u);
    EXPECT_EQ(pockets[0].a, 3);
    EXPECT_EQ(pockets[0].b, 3); // bottom-right
    EXPECT_TRUE(result.bodies[0].pocketed);
    EXPECT_EQ(result.bodies[0].vel_px_s, Vec2{});
    const Vec2 pocket = c.pocket_centres()[3];
    EXPECT_LT(length(pockets[0].pos_px - pocket), c.pocket_radius_px);
    EXPECT_FALSE(result.bodies[1].pocketed);
}

TEST(FixedStep, PocketedBodiesTakeNoPart) {
    const PhysicsConfig c;
    std::vector<Body> bodies{coin(0, {100, 300}, {300, 0}), coin(1, {140, 300})};
    bodies[1].pocketed = true;
    const auto result = simulate_fixed_step(c, bodies, options_with(1.0 / 60.0, 0.5));
    EXPECT_TRUE(events_of(result, EventKind::Collision).empty());
    EXPECT_EQ(result.bodies[1].pos_px, (Vec2{140, 300}));
}

// A head-on hit at rest: J = (1 + e) m_a m_b / (m_a + m_b) v_n, momentum conserved, relative
// normal velocity reversed and scaled by e.
void expect_head_on(const Body& mover, double mass_mover, double mass_target) {
    const PhysicsConfig c;
    const Body target = coin(1, {300, 300});
    const std::vector<Body> bodies{mover, target};
    const double h = 1.0 / 240.0;
    const auto full = simulate_fixed_step(c, bodies, options_with(h, 0.5));
    const auto hits = events_of(full, EventKind::Collision);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].a, mover.id);
    EXPECT_EQ(hits[0].b, 1);
    const double n = std::round(hits[0].t_s / h);
    const double v_n = mover.vel_px_s.x * std::pow(std::exp(-c.damping_per_s * h), n);
    const double j = 1.9 * mass_mover * mass_target / (mass_mover + mass_target) * v_n;
    EXPECT_NEAR(hits[0].impulse, j, 1e-9);

    const auto at_hit = simulate_fixed_step(c, bodies, options_with(h, hits[0].t_s));
    const Vec2 va = at_hit.bodies[0].vel_px_s;
    const Vec2 vb = at_hit.bodies[1].vel_px_s;
    EXPECT_NEAR(mass_mover * va.x + mass_target * vb.x, mass_mover * v_n, 1e-9);
    EXPECT_NEAR(vb.x - va.x, 0.9 * v_n, 1e-9);
    EXPECT_EQ(va.y, 0.0);
    EXPECT_EQ(vb.y, 0.0);
}

TEST(FixedStep, HeadOnCoinCoinExchangesMomentumAsTheFormulaSays) {
    expect_head_on(coin(0, {200, 300}, {500, 0}), 1.0, 1.0);
}

TEST(FixedStep, HeadOnStrikerCoinExchangesMomentumAsTheFormulaSays) {
    expect_head_on(striker(0, {200, 300}, {500, 0}), 2.0, 1.0);
}

TEST(FixedStep, OverlappingPairsArePushedApartByHalfTheOverlapPlusHalfAPixel) {
    const PhysicsConfig c;
    // Bodies 0 and 1 overlap by 8 px and rest; body 2 moves so that a step is taken.
    const std::vector<Body> bodies{coin(0, {300, 300}), coin(1, {320, 300}),
                                   coin(2, {100, 500}, {100, 0})};
    const auto result = simulate_fixed_step(c, bodies, options_with(1.0 / 60.0, 1.0 / 60.0));
    EXPECT_DOUBLE_EQ(result.bodies[0].pos_px.x, 300.0 - 4.5);
    EXPECT_DOUBLE_EQ(result.bodies[1].pos_px.x, 320.0 + 4.5);
    EXPECT_TRUE(events_of(result, EventKind::Collision).empty());
}

TEST(FixedStep, SeparatingOverlappingPairGetsNoImpulse) {
    const PhysicsConfig c;
    const std::vector<Body> bodies{coin(0, {300, 300}, {-100, 0}), coin(1, {320, 300}, {100, 0})};
    const auto result = simulate_fixed_step(c, bodies, options_with(1.0 / 60.0, 1.0 / 60.0));
    EXPECT_TRUE(events_of(result, EventKind::Collision).empty());
    EXPECT_LT(result.bodies[0].vel_px_s.x, 0.0);
    EXPECT_GT(result.bodies[1].vel_px_s.x, 0.0);
}

TEST(FixedStep, EndsAtMaxTimeWhenNothingStops) {
    PhysicsConfig c;
    c.damping_per_s = 1e-3; // would take hours to stop
    c.cushion_restitution = 1.0;
    const std::vector<Body> one{coin(0, {300, 300}, {700, 300})};
    FixedStepOptions options = options_with(1.0 / 60.0);
    options.max_time_s = 2.0;
    const auto result = simulate_fixed_step(c, one, options);
    EXPECT_EQ(result.end_time_s, 2.0);
    EXPECT_EQ(result.steps, 120);
    EXPECT_NEAR(length(result.bodies[0].vel_px_s), length(Vec2{700, 300}) * std::exp(-2e-3), 1e-9);
    EXPECT_GE(events_of(result, EventKind::Cushion).size(), 3u);
}

TEST(FixedStep, UntilBetweenStepsEndsWithAShortStep) {
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {100, 300}, {300, 0})};
    const auto result = simulate_fixed_step(c, one, options_with(1.0 / 60.0, 0.025));
    EXPECT_EQ(result.steps, 2);
    EXPECT_EQ(result.end_time_s, 0.025);
    const double d = std::exp(-c.damping_per_s / 60.0);
    EXPECT_NEAR(result.bodies[0].pos_px.x, 100.0 + 300.0 / 60.0 + 300.0 * d / 120.0, 1e-9);
}

TEST(FixedStep, InvalidStepSimulatesNothing) {
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {100, 300}, {300, 0})};
    for (double dt : {0.0, -1.0, std::nan("")}) {
        const auto result = simulate_fixed_step(c, one, options_with(dt));
        EXPECT_EQ(result.steps, 0);
        EXPECT_EQ(result.bodies[0].pos_px, one[0].pos_px);
    }
}

TEST(FixedStep, IsDeterministic) {
    const PhysicsConfig c;
    std::vector<Body> bodies;
    for (int i = 0; i < 12; ++i) {
        bodies.push_back(coin(i, {120.0 + 30.0 * i, 150.0 + 20.0 * (i % 5)}));
    }
    bodies.push_back(striker(19, {300, 520}, {137, -1450}));
    const auto a = simulate_fixed_step(c, bodies, options_with(1.0 / 120.0));
    const auto b = simulate_fixed_step(c, bodies, options_with(1.0 / 120.0));
    ASSERT_EQ(a.events.size(), b.events.size());
    EXPECT_GT(a.events.size(), 3u);
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        EXPECT_EQ(a.bodies[i].pos_px, b.bodies[i].pos_px);
    }
    EXPECT_EQ(a.end_time_s, b.end_time_s);
}

TEST(FixedStep, NoEventsWhenNotRecorded) {
    const PhysicsConfig c;
    const std::vector<Body> one{coin(0, {60, 300}, {-600, 0})};
    FixedStepOptions options = options_with(1.0 / 60.0);
    options.record_events = false;
    const auto result = simulate_fixed_step(c, one, options);
    EXPECT_TRUE(result.events.empty());
    EXPECT_GT(result.steps, 0);
}

} // namespace
} // namespace carrom
