// Determinism (bit-identical repeats), the simultaneous-contact policy (a mirror-symmetric break
// stays mirror-symmetric) and scene validation.

#include "common/physics_test_util.hpp"

#include <cmath>
#include <cstring>

namespace carrom {
namespace {

using test::coin;
using test::same_bits;
using test::striker;

std::vector<Body> centred_break(const PhysicsConfig& config, double speed = 1500.0) {
    std::vector<Body> scene = standard_layout(config);
    scene.push_back(striker(kStrikerId, 300.0, 520.0, 0.0, -speed));
    return scene;
}

TEST(ExactDeterminism, RepeatsAreBitIdenticalAndEngineReuseChangesNothing) {
    const PhysicsConfig config;
    const std::vector<Body> scene = centred_break(config);
    const SimulateResult first = simulate_exact(config, scene);
    ExactEngine engine(config);
    // Run something else on the same engine first: no state may leak between runs.
    engine.run(std::vector<Body>{coin(1, 100.0, 100.0, 300.0, 200.0)});
    const SimResult& again = *engine.run(scene).result;
    ASSERT_EQ(first.result.events.size(), again.events.size());
    for (std::size_t i = 0; i < again.events.size(); ++i) {
        const Event& a = first.result.events[i];
        const Event& b = again.events[i];
        EXPECT_TRUE(same_bits(a.t_s, b.t_s) && a.kind == b.kind && a.a == b.a && a.b == b.b &&
                    same_bits(a.impulse, b.impulse))
            << "event " << i;
    }
    for (std::size_t i = 0; i < scene.size(); ++i) {
        EXPECT_TRUE(same_bits(first.result.bodies[i].pos_px.x, again.bodies[i].pos_px.x));
        EXPECT_TRUE(same_bits(first.result.bodies[i].pos_px.y, again.bodies[i].pos_px.y));
    }
}

// Scenes of more than 64 bodies skip the bit-mask broad phase and test every pair. Pocketed
// bodies take no part, so padding the break with pocketed coins must change nothing: both paths
// give the same events and final state, to the bit.
TEST(ExactDeterminism, BroadPhaseWithoutBitMasksGivesTheSameBreak) {
    const PhysicsConfig config;
    const std::vector<Body> scene = centred_break(config, 1234.5);
    std::vector<Body> padded = scene;
    for (int i = 0; i < 50; ++i) {
        Body extra = coin(1000 + i, 57.0, 57.0);
        extra.pocketed = true;
        padded.push_back(extra);
    }
    ASSERT_GT(padded.size(), 64U);
    const SimulateResult small = simulate_exact(config, scene);
    const SimulateResult large = simulate_exact(config, padded);
    ASSERT_FALSE(small.error);
    ASSERT_FALSE(large.error);
    ASSERT_EQ(small.result.events.size(), large.result.events.size());
    ASSERT_GT(small.result.events.size(), 20U);
    for (std::size_t i = 0; i < small.result.events.size(); ++i) {
        const Event& a = small.result.events[i];
        const Event& b = large.result.events[i];
        EXPECT_TRUE(same_bits(a.t_s, b.t_s) && a.kind == b.kind && a.a == b.a && a.b == b.b &&
                    same_bits(a.impulse, b.impulse) && same_bits(a.pos_px.x, b.pos_px.x) &&
                    same_bits(a.pos_px.y, b.pos_px.y))
            << "event " << i;
    }
    for (std::size_t i = 0; i < scene.size(); ++i) {
        const Body& a = small.result.bodies[i];
        const Body& b = large.result.bodies[i];
        EXPECT_TRUE(same_bits(a.pos_px.x, b.pos_px.x) && same_bits(a.pos_px.y, b.pos_px.y) &&
                    a.pocketed == b.pocketed)
            << "body " << a.id;
    }
}

TEST(ExactDeterminism, StandardLayoutIsExactlyMirrorSymmetric) {
    const PhysicsConfig config;
    const std::vector<Body> layout = standard_layout(config);
    for (const Body& b : layout) {
        const Vec2 mirror{600.0 - b.pos_px.x, b.pos_px.y};
        int matches = 0;
        for (const Body& other : layout) {
            matches += other.pos_px == mirror ? 1 : 0;
        }
        EXPECT_EQ(matches, 1) << "body " << b.id;
    }
}

TEST(ExactDeterminism, CentredBreakIsMirrorSymmetricWithin1e9Px) {
    const PhysicsConfig config;
    for (double speed : {1500.0, 900.0, 400.0}) {
        const std::vector<Body> scene = centred_break(config, speed);
        const SimulateResult sim = simulate_exact(config, scene);
        ASSERT_FALSE(sim.error);
        // The striker meets two coins at the same instant: they are resolved together.
        EXPECT_GE(sim.result.stats.contact_rounds, 1);
        for (std::size_t i = 0; i < scene.size(); ++i) {
            const Vec2 start_mirror{600.0 - scene[i].pos_px.x, scene[i].pos_px.y};
            std::size_t partner = scene.size();
            for (std::size_t j = 0; j < scene.size(); ++j) {
                if (scene[j].pos_px == start_mirror) {
                    partner = j;
                }
            }
            ASSERT_LT(partner, scene.size()) << "body " << scene[i].id;
            const Body& a = sim.result.bodies[i];
            const Body& b = sim.result.bodies[partner];
            EXPECT_EQ(a.pocketed, b.pocketed);
            EXPECT_NEAR(a.pos_px.x, 600.0 - b.pos_px.x, 1e-9) << "bodies " << a.id << ", " << b.id;
            EXPECT_NEAR(a.pos_px.y, b.pos_px.y, 1e-9) << "bodies " << a.id << ", " << b.id;
        }
    }
}

TEST(ExactDeterminism, SimultaneousImpactOnTwoCoinsConservesMomentumAndLosesEnergy) {
    const PhysicsConfig config;
    // Striker moving up meets two coins placed symmetrically at +-30 degrees at one instant.
    const double reach = 32.0;
    const std::vector<Body> scene{striker(19, 300.0, 400.0, 0.0, -600.0),
                                  coin(1, 300.0 - reach * 0.5, 300.0),
                                  coin(2, 300.0 + reach * 0.5, 300.0)};
    SimOptions options;
    options.until_s = 0.2; // just after the impact, before anything stops
    const SimulateResult sim = simulate_exact(config, scene, options);
    ASSERT_FALSE(sim.error);
    int collisions = 0;
    double first_time = -1.0;
    for (const Event& e : sim.result.events) {
        if (e.kind == EventKind::Collision) {
            ++collisions;
            if (first_time < 0.0) {
                first_time = e.t_s;
            }
            EXPECT_EQ(e.t_s, first_time) << "both contacts at the same instant";
        }
    }
    EXPECT_EQ(collisions, 2);
    const auto& b = sim.result.bodies;
    EXPECT_NEAR(b[1].vel_px_s.x, -b[2].vel_px_s.x, 1e-9);
    EXPECT_NEAR(b[1].vel_px_s.y, b[2].vel_px_s.y, 1e-9);
    EXPECT_NEAR(b[0].vel_px_s.x, 0.0, 1e-9);
    // Momentum along y just after the impact equals the momentum the striker carried then.
    const double decay = std::exp(-config.damping_per_s * 0.2);
    const double momentum = 2.0 * b[0].vel_px_s.y + b[1].vel_px_s.y + b[2].vel_px_s.y;
    EXPECT_NEAR(momentum, 2.0 * -600.0 * decay, 1e-6);
    const double energy = test::kinetic_energy(config, b);
    EXPECT_LT(energy, 0.5 * 2.0 * 600.0 * 600.0 * decay * decay);
}

TEST(ExactValidation, OverlappingBodiesAreRejectedNamingTheBody) {
    const PhysicsConfig config;
    const SimulateResult sim =
        simulate_exact(config, std::vector<Body>{coin(4, 300.0, 300.0), coin(7, 320.0, 300.0)});
    ASSERT_TRUE(sim.error);
    EXPECT_EQ(sim.error->code, "overlap");
    EXPECT_EQ(sim.error->body_id, 7);
    EXPECT_EQ(sim.error->field, "pos");
    EXPECT_NE(sim.error->message.find("body 7 overlaps body 4"), std::string::npos);
}

TEST(ExactValidation, BodyOutsideTheCushionsIsRejectedNamingTheField) {
    const PhysicsConfig config;
    const SimulateResult sim = simulate_exact(config, std::vector<Body>{coin(3, 300.0, 40.0)});
    ASSERT_TRUE(sim.error);
    EXPECT_EQ(sim.error->code, "outside_cushions");
    EXPECT_EQ(sim.error->body_id, 3);
    EXPECT_EQ(sim.error->field, "pos.y");
}

TEST(ExactValidation, ACentreARoundingErrorOutsideTheCushionIsAccepted) {
    const PhysicsConfig config;
    const double limit = config.cushion_max(config.coin_radius_px);
    EXPECT_FALSE(validate_scene(config, std::vector<Body>{coin(1, 300.0, limit + 1e-9)}));
    ASSERT_TRUE(validate_scene(config, std::vector<Body>{coin(1, 300.0, limit + 1e-5)}));
}

TEST(ExactValidation, EveryFinalStateOfRandomShotsIsAValidScene) {
    const PhysicsConfig config;
    ExactEngine engine(config);
    for (int i = 0; i < 200; ++i) {
        std::vector<Body> scene = standard_layout(config);
        const double x = baseline_x_min(config) + 1.87 * i;
        scene.push_back(make_striker(config, Baseline::Bottom, {x, -0.3 - 0.0127 * i, 25.0}));
        const SimResult& result = *engine.run(scene).result;
        std::vector<Body> after = result.bodies;
        after.pop_back(); // the striker leaves the board after the shot
        const auto error = validate_scene(config, after);
        EXPECT_FALSE(error) << "shot " << i << ": " << (error ? error->message : "");
    }
}

TEST(ExactValidation, NonFiniteNumbersAreRejectedNamingTheField) {
    const PhysicsConfig config;
    const double nan = std::nan("");
    const double inf = INFINITY;
    const std::pair<Body, const char*> cases[] = {{coin(1, nan, 300.0), "pos.x"},
                                                  {coin(1, 300.0, inf), "pos.y"},
                                                  {coin(1, 300.0, 300.0, -inf, 0.0), "vel.x"},
                                                  {coin(1, 300.0, 300.0, 0.0, nan), "vel.y"}};
    for (const auto& [body, field] : cases) {
        const SimulateResult sim = simulate_exact(config, std::vector<Body>{body});
        ASSERT_TRUE(sim.error) << field;
        EXPECT_EQ(sim.error->code, "not_finite");
        EXPECT_EQ(sim.error->field, field);
        EXPECT_EQ(sim.error->body_id, 1);
    }
}

TEST(ExactValidation, DuplicateIdsAreRejected) {
    const PhysicsConfig config;
    const SimulateResult sim =
        simulate_exact(config, std::vector<Body>{coin(5, 100.0, 100.0), coin(5, 200.0, 200.0)});
    ASSERT_TRUE(sim.error);
    EXPECT_EQ(sim.error->code, "duplicate_id");
    EXPECT_EQ(sim.error->body_id, 5);
}

TEST(ExactValidation, DuplicateIdsOfAnyValueAreRejectedAtTheSecondBody) {
    const PhysicsConfig config;
    // Ids below 0, in 0..63 and above 63 take different paths in validate_scene.
    for (const int id : {-3, 0, 63, 64, 1000}) {
        const std::vector<Body> scene{coin(7, 100.0, 100.0), coin(id, 200.0, 200.0),
                                      coin(id == 9 ? 8 : 9, 300.0, 300.0), coin(id, 400.0, 400.0)};
        const auto error = validate_scene(config, scene);
        ASSERT_TRUE(error) << id;
        EXPECT_EQ(error->code, "duplicate_id") << id;
        EXPECT_EQ(error->body_id, id);
    }
    EXPECT_FALSE(
        validate_scene(config, std::vector<Body>{coin(-1, 100.0, 100.0), coin(63, 200.0, 200.0),
                                                 coin(64, 300.0, 300.0)}));
}

TEST(ExactValidation, TheFirstOverlappingPairInInputOrderIsReported) {
    const PhysicsConfig config;
    Body gone = coin(2, 305.0, 300.0);
    gone.pocketed = true;
    // 4 overlaps 6 and 9 overlaps 6; the pair (4, 6) comes first; the pocketed body is ignored.
    const auto error =
        validate_scene(config, std::vector<Body>{coin(1, 100.0, 100.0), coin(4, 300.0, 300.0), gone,
                                                 coin(9, 300.0, 335.0), coin(6, 300.0, 318.0)});
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "overlap");
    EXPECT_EQ(error->body_id, 6);
    EXPECT_NE(error->message.find("body 6 overlaps body 4"), std::string::npos);
}

TEST(ExactValidation, PocketedBodiesMayOverlapAndLieAnywhere) {
    const PhysicsConfig config;
    Body gone = coin(2, 20.0, 20.0);
    gone.pocketed = true;
    const SimulateResult sim =
        simulate_exact(config, std::vector<Body>{coin(1, 300.0, 300.0, 50.0, 0.0), gone});
    EXPECT_FALSE(sim.error);
    EXPECT_TRUE(sim.result.bodies[1].pocketed);
    EXPECT_EQ(sim.result.bodies[1].pos_px, (Vec2{20.0, 20.0}));
}

TEST(ExactValidation, ConfigErrorsNameTheField) {
    PhysicsConfig config;
    config.disc_restitution = 1.5;
    ASSERT_TRUE(validate_config(config));
    EXPECT_EQ(validate_config(config)->field, "disc_restitution");
    config = {};
    config.damping_per_s = std::nan("");
    EXPECT_EQ(validate_config(config)->field, "damping_per_s");
    EXPECT_FALSE(validate_config(PhysicsConfig{}));
}

} // namespace
} // namespace carrom
