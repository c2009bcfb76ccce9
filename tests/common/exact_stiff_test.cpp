// Stiff and extreme scenes. After every event: no overlap beyond 1e-6 px, kinetic energy never
// increases, every body inside the cushions or pocketed; and every scene terminates within a
// bounded number of events.

#include "common/physics_test_util.hpp"

#include <cmath>
#include <random>

namespace carrom {
namespace {

using test::coin;
using test::expect_invariants;
using test::run_checked;
using test::striker;

TEST(ExactStiff, TouchingBodiesAtRestAreStruck) {
    const PhysicsConfig config;
    const std::vector<Body> scene{coin(1, 300.0, 300.0), coin(2, 328.0, 300.0),
                                  coin(3, 314.0, 300.0 + 14.0 * std::sqrt(3.0)),
                                  striker(19, 200.0, 300.0, 900.0, 0.0)};
    expect_invariants(run_checked(config, scene), 200);
}

TEST(ExactStiff, NearlyTouchingBodiesAHairApart) {
    const PhysicsConfig config;
    for (double gap : {1e-12, 1e-9, 1e-7}) {
        const std::vector<Body> scene{coin(1, 300.0, 300.0), coin(2, 328.0 + gap, 300.0),
                                      coin(3, 356.0 + 2.0 * gap, 300.0),
                                      coin(4, 200.0, 300.0, 700.0, 0.0)};
        expect_invariants(run_checked(config, scene), 100);
    }
}

TEST(ExactStiff, NewtonsCradleSendsTheLastCoinOff) {
    const PhysicsConfig config;
    std::vector<Body> scene;
    for (int i = 0; i < 5; ++i) {
        scene.push_back(coin(i + 1, 250.0 + 28.0 * i, 300.0));
    }
    scene.push_back(coin(9, 150.0, 300.0, 250.0, 0.0)); // the far coin stops before the cushion
    expect_invariants(run_checked(config, scene), 400);
    const SimulateResult sim = simulate_exact(config, scene);
    // Momentum passes down the chain one contact at a time: the far coin travels furthest and
    // every coin before it moves much less.
    const double far = sim.result.bodies[4].pos_px.x - 362.0;
    EXPECT_GT(far, 100.0);
    for (int i = 0; i < 4; ++i) {
        EXPECT_LT(sim.result.bodies[static_cast<std::size_t>(i)].pos_px.x - (250.0 + 28.0 * i),
                  0.2 * far)
            << "coin " << i + 1;
    }
}

TEST(ExactStiff, CoinPinnedBetweenCushionAndCoin) {
    const PhysicsConfig config;
    const double wall = config.cushion_max(config.coin_radius_px);
    for (double e : {0.9, 0.5, 0.1, 0.0}) {
        PhysicsConfig c = config;
        c.disc_restitution = e;
        c.cushion_restitution = std::min(e, 0.8);
        const std::vector<Body> scene{coin(1, wall, 300.0),
                                      coin(2, wall - 28.0, 300.0, 800.0, 0.0)};
        expect_invariants(run_checked(c, scene), 200);
        const std::vector<Body> struck{coin(1, wall, 300.0), coin(2, wall - 28.0, 300.0),
                                       striker(19, 300.0, 300.0, 1500.0, 0.0)};
        expect_invariants(run_checked(c, struck), 400);
    }
}

TEST(ExactStiff, LowRestitutionBreakEndsInBoundedEvents) {
    for (double e : {0.0, 0.1, 0.3}) {
        PhysicsConfig config;
        config.disc_restitution = e;
        std::vector<Body> scene = standard_layout(config);
        scene.push_back(striker(kStrikerId, 300.0, 520.0, 0.0, -1500.0));
        expect_invariants(run_checked(config, scene), 2000);
    }
}

TEST(ExactStiff, ZeroTimeCascadeIsEndedByTheCollapseSolve) {
    // A row of touching coins pressed into a cushion by a very heavy striker, with restitution
    // 1 everywhere: the impulse runs up and down the row thousands of times at one instant
    // (about pi sqrt(M / m) reflections off the striker) before the striker turns back; the
    // plastic group solve ends it.
    PhysicsConfig config;
    config.disc_restitution = 1.0;
    config.cushion_restitution = 1.0;
    config.striker_mass = 1e4;
    const double wall = config.cushion_max(config.coin_radius_px);
    std::vector<Body> scene;
    for (int i = 0; i < 6; ++i) {
        scene.push_back(coin(i + 1, wall - 28.0 * i, 300.0, 0.0, 0.0));
    }
    scene.push_back(striker(19, wall - 28.0 * 5 - 32.0, 300.0, 1200.0, 0.0));
    const test::InvariantReport report = run_checked(config, scene);
    expect_invariants(report, 2000);
    EXPECT_GE(simulate_exact(config, scene).result.stats.collapse_solves, 1);
}

TEST(ExactStiff, GrazingContacts) {
    const PhysicsConfig config;
    for (double miss : {-1e-6, -1e-9, 0.0, 1e-9, 1e-6}) {
        const double h = 28.0 + miss; // centre offset: touching exactly at 28 px
        const std::vector<Body> scene{coin(1, 200.0, 300.0 + h, 500.0, 0.0), coin(2, 300.0, 300.0)};
        expect_invariants(run_checked(config, scene), 50);
        const SimulateResult sim = simulate_exact(config, scene);
        if (miss > 0.0) {
            EXPECT_EQ(sim.result.bodies[1].pos_px, (Vec2{300.0, 300.0})) << "a miss moves nothing";
        }
        // A graze can only push the resting coin a tiny amount.
        EXPECT_LT(length(sim.result.bodies[1].pos_px - Vec2{300.0, 300.0}), 1e-2) << miss;
    }
}

TEST(ExactStiff, SpeedsFromAThousandthToAMillionPxPerSecond) {
    const PhysicsConfig config;
    for (double speed : {1e-3, 1.0, 10.0, 100.0, 1e3, 1e4, 1e5, 1e6}) {
        std::vector<Body> scene = standard_layout(config);
        scene.push_back(striker(kStrikerId, 290.0, 520.0, 0.05 * speed, -speed));
        const test::InvariantReport report = run_checked(config, scene);
        expect_invariants(report, 20000);
    }
}

TEST(ExactStiff, RandomShotsKeepEveryInvariant) {
    const PhysicsConfig config;
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> x(baseline_x_min(config), baseline_x_max(config));
    std::uniform_real_distribution<double> angle(-2.8, -0.35);
    std::uniform_real_distribution<double> power(0.0, config.max_power);
    for (int shot = 0; shot < 60; ++shot) {
        std::vector<Body> scene = standard_layout(config);
        scene.push_back(make_striker(config, Baseline::Bottom, {x(rng), angle(rng), power(rng)}));
        expect_invariants(run_checked(config, scene), 5000);
    }
}

// Coin 1 slides 10 px to the right and stops at t = 1.02 s, in the path of coin 2, which
// reaches that spot at about t = 1.5 s. When coin 2's first prediction is made, coin 1 is still
// moving, and their lines meet only after coin 1's stop, so that prediction names its own stop
// instead. The engine must see the contact once coin 1 is at rest (in this engine through the
// prediction of the body at rest): one collision of 1 and 2, after coin 1's stop, and no
// overlap. With 63 more coins at rest along the top cushion the scene has 65 bodies, which
// takes the engine's general path for scenes of more than 64.
TEST(ExactStiff, ACoinThatStopsInAMoversPathIsStillHit) {
    const PhysicsConfig config;
    const double k = config.damping_per_s;
    const double slide_px = 10.0;                                     // (v - stop speed) / k
    const double coin1_speed = config.stop_speed_px_s + k * slide_px; // px/s
    const double travel = (1.0 - std::exp(-k * 1.5)) / k;             // travel factor at 1.5 s, s
    const double coin2_speed = (500.0 - 328.0) / travel;              // px/s
    for (int extra : {0, 63}) {
        std::vector<Body> scene{coin(1, 300.0, 300.0, coin1_speed, 0.0),
                                coin(2, 300.0 + slide_px, 500.0, 0.0, -coin2_speed)};
        for (int e = 0; e < extra; ++e) {
            scene.push_back(coin(100 + e, 50.0 + 28.0 * (e % 17), 50.0 + 28.0 * (e / 17)));
        }
        const SimulateResult sim = simulate_exact(config, scene);
        ASSERT_FALSE(sim.error.has_value()) << sim.error->message;
        int collisions = 0;
        double coin1_stop_s = -1.0;
        for (const Event& event : sim.result.events) {
            if (event.kind == EventKind::Stop && event.a == 1 && coin1_stop_s < 0.0) {
                coin1_stop_s = event.t_s;
            }
            if (event.kind == EventKind::Collision) {
                ++collisions;
                EXPECT_EQ(event.a + event.b, 3) << "extra " << extra;
                EXPECT_GT(coin1_stop_s, 0.0) << "extra " << extra;
            }
        }
        EXPECT_EQ(collisions, 1) << "extra " << extra;
        expect_invariants(run_checked(config, scene), 20);
    }
}

} // namespace
} // namespace carrom
