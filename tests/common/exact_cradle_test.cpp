// Newton's cradle: a coin strikes a straight row of touching coins. The contacts at the instant
// of impact are resolved one round at a time; however long the row (up to 19 coins) and for e
// from 0.5 to 1, the cascade ends without the plastic collapse solve, which is kept for true
// zero-time collapse (ExactStiff.ZeroTimeCascadeIsEndedByTheCollapseSolve).

#include "common/physics_test_util.hpp"

#include <cmath>

namespace carrom {
namespace {

using test::coin;

constexpr double kRadius = 10.0;       // px: 19 touching coins fit between the cushions
constexpr double kFirstX = 150.0;      // px, the first coin of the row
constexpr double kStrikeSpeed = 600.0; // px/s
constexpr double kUntil = 0.02;        // s: after the impact (at 1/60 s), before anything else

struct Cradle {
    PhysicsConfig config;
    std::vector<Body> scene; // the row, then the striking coin
};

Cradle make_cradle(int coins, double e) {
    Cradle c;
    c.config.coin_radius_px = kRadius;
    c.config.disc_restitution = e;
    for (int i = 0; i < coins; ++i) {
        c.scene.push_back(coin(i + 1, kFirstX + 2.0 * kRadius * i, 300.0));
    }
    c.scene.push_back(coin(100, kFirstX - 3.0 * kRadius, 300.0, kStrikeSpeed, 0.0));
    return c;
}

TEST(ExactCradle, LongRowsNeedNoCollapseSolve) {
    for (int coins = 2; coins <= 19; ++coins) {
        for (double e : {0.5, 0.6, 0.7, 0.8, 0.9, 0.95, 1.0}) {
            const Cradle c = make_cradle(coins, e);
            SimOptions options;
            options.until_s = kUntil;
            const SimulateResult run = simulate_exact(c.config, c.scene, options);
            ASSERT_FALSE(run.error);
            const SimResult& r = run.result;
            EXPECT_EQ(r.stats.collapse_solves, 0) << coins << " coins, e = " << e;
            // Momentum is kept (all bodies share the damping, so it decays as e^(-k t)).
            const double k = c.config.damping_per_s;
            double momentum = 0.0;
            for (const Body& b : r.bodies) {
                momentum += b.vel_px_s.x;
            }
            EXPECT_NEAR(momentum, kStrikeSpeed * std::exp(-k * kUntil), 1e-9)
                << coins << " coins, e = " << e;
            // No pair of neighbours approaches faster than the engine's approach tolerance
            // (1e-8 px/s; the cascade converges geometrically and ends there): the striking
            // coin, then the row in order.
            double behind = r.bodies.back().vel_px_s.x;
            for (int i = 0; i < coins; ++i) {
                const double v = r.bodies[static_cast<std::size_t>(i)].vel_px_s.x;
                EXPECT_GE(v, behind - 2e-8) << coins << " coins, e = " << e << ", coin " << i + 1;
                behind = v;
            }
        }
    }
}

// At e = 1 the whole momentum passes down the row: the last coin leaves at the striking speed
// and every other coin is left at rest.
TEST(ExactCradle, ElasticRowPassesEverythingToTheLastCoin) {
    for (int coins = 2; coins <= 19; ++coins) {
        const Cradle c = make_cradle(coins, 1.0);
        SimOptions options;
        options.until_s = kUntil;
        const SimulateResult run = simulate_exact(c.config, c.scene, options);
        ASSERT_FALSE(run.error);
        const std::vector<Body>& bodies = run.result.bodies;
        const double k = c.config.damping_per_s;
        EXPECT_NEAR(bodies[static_cast<std::size_t>(coins - 1)].vel_px_s.x,
                    kStrikeSpeed * std::exp(-k * kUntil), 1e-9)
            << coins << " coins";
        for (std::size_t i = 0; i + 1 < bodies.size(); ++i) {
            if (i != static_cast<std::size_t>(coins - 1)) {
                EXPECT_EQ(length(bodies[i].vel_px_s), 0.0) << coins << " coins, body " << i;
            }
        }
    }
}

} // namespace
} // namespace carrom
