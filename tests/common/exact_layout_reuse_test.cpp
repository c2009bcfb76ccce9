// An ExactEngine reused across scenes keeps what the last scene's set-up computed for the bodies
// at rest (validation of their pairs, path boxes, near rows) and reuses it for bodies that are
// bit for bit the same in the next scene. None of that may show in a result: every run must give
// what a fresh engine gives, to the bit, and every invalid scene must still be rejected with the
// error a fresh validation reports.

#include "common/physics_test_util.hpp"

#include <cstring>
#include <numbers>
#include <random>

namespace carrom {
namespace {

using test::coin;
using test::same_bits;
using test::striker;

// Events and final state equal to the bit.
void expect_same_result(const SimResult& fresh, const SimResult& reused, const std::string& what) {
    ASSERT_EQ(fresh.events.size(), reused.events.size()) << what;
    for (std::size_t i = 0; i < fresh.events.size(); ++i) {
        const Event& a = fresh.events[i];
        const Event& b = reused.events[i];
        ASSERT_TRUE(same_bits(a.t_s, b.t_s) && a.kind == b.kind && a.a == b.a && a.b == b.b &&
                    same_bits(a.impulse, b.impulse))
            << what << ", event " << i;
    }
    ASSERT_EQ(fresh.bodies.size(), reused.bodies.size()) << what;
    for (std::size_t i = 0; i < fresh.bodies.size(); ++i) {
        const Body& a = fresh.bodies[i];
        const Body& b = reused.bodies[i];
        ASSERT_TRUE(same_bits(a.pos_px.x, b.pos_px.x) && same_bits(a.pos_px.y, b.pos_px.y) &&
                    same_bits(a.vel_px_s.x, b.vel_px_s.x) && a.pocketed == b.pocketed)
            << what << ", body " << i;
    }
    EXPECT_EQ(fresh.pocket_order, reused.pocket_order) << what;
    EXPECT_EQ(fresh.collision_counts, reused.collision_counts) << what;
}

std::vector<Body> with_striker(std::vector<Body> layout, double x, double angle, double power) {
    const PhysicsConfig config;
    layout.push_back(make_striker(config, Baseline::Bottom, Shot{x, angle, power}));
    return layout;
}

TEST(ExactLayoutReuse, ShotsFromOneLayoutGiveTheResultsOfAFreshEngine) {
    const PhysicsConfig config;
    const std::vector<Body> layout = standard_layout(config);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> x(baseline_x_min(config), baseline_x_max(config));
    std::uniform_real_distribution<double> angle(-std::numbers::pi * 5.0 / 6.0,
                                                 -std::numbers::pi / 6.0);
    std::uniform_real_distribution<double> power(1.0, 25.0);
    ExactEngine engine(config);
    for (int shot = 0; shot < 200; ++shot) {
        const std::vector<Body> scene = with_striker(layout, x(rng), angle(rng), power(rng));
        const SimulateResult fresh = simulate_exact(config, scene);
        const ExactEngine::Outcome reused = engine.run(scene);
        ASSERT_FALSE(fresh.error);
        ASSERT_TRUE(reused.result);
        expect_same_result(fresh.result, *reused.result, "shot " + std::to_string(shot));
    }
}

// Each scene differs from the one before in a way the reuse must notice: a coin moved, a coin
// given a velocity, a coin pocketed, a coin brought back, -0.0 for 0.0, another size.
TEST(ExactLayoutReuse, ChangedBodiesAreNotTakenFromTheLastScene) {
    const PhysicsConfig config;
    const std::vector<Body> layout = standard_layout(config);
    std::vector<std::vector<Body>> scenes;
    scenes.push_back(with_striker(layout, 300.0, -std::numbers::pi / 2.0, 25.0));
    std::vector<Body> moved = layout;
    moved[7].pos_px = {300.0, 430.0}; // off the ring, into the path of the centred striker
    scenes.push_back(with_striker(moved, 300.0, -std::numbers::pi / 2.0, 25.0));
    std::vector<Body> rolling = moved;
    rolling[5].vel_px_s = {40.0, -30.0};
    scenes.push_back(with_striker(rolling, 300.0, -std::numbers::pi / 2.0, 25.0));
    std::vector<Body> pocketed = moved;
    pocketed[0].pocketed = true; // the queen: the centre is open now
    scenes.push_back(with_striker(pocketed, 300.0, -std::numbers::pi / 2.0, 25.0));
    scenes.push_back(with_striker(moved, 300.0, -std::numbers::pi / 2.0, 25.0));
    std::vector<Body> negative_zero = moved;
    negative_zero[7].vel_px_s = {-0.0, 0.0};
    scenes.push_back(with_striker(negative_zero, 300.0, -std::numbers::pi / 2.0, 25.0));
    std::vector<Body> fewer(moved.begin(), moved.begin() + 10);
    scenes.push_back(with_striker(fewer, 300.0, -std::numbers::pi / 2.0, 25.0));
    scenes.push_back(with_striker(layout, 250.0, -std::numbers::pi / 3.0, 20.0));
    ExactEngine engine(config);
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const SimulateResult fresh = simulate_exact(config, scenes[i]);
        const ExactEngine::Outcome reused = engine.run(scenes[i]);
        ASSERT_FALSE(fresh.error) << "scene " << i;
        ASSERT_TRUE(reused.result) << "scene " << i;
        expect_same_result(fresh.result, *reused.result, "scene " + std::to_string(i));
    }
}

// An engine that has just simulated a valid shot on the standard layout.
class AfterAValidLayout : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(engine.run(with_striker(layout, 300.0, -std::numbers::pi / 2.0, 10.0)).result);
    }
    const PhysicsConfig config;
    const std::vector<Body> layout = standard_layout(config);
    ExactEngine engine{config};
};

TEST_F(AfterAValidLayout, ACoinMovedOntoAnotherIsRejected) {
    std::vector<Body> bad = layout;
    bad[1].pos_px = bad[0].pos_px + Vec2{10.0, 0.0}; // inner-ring coin 1 onto the queen
    const std::vector<Body> scene = with_striker(bad, 300.0, -std::numbers::pi / 2.0, 10.0);
    const ExactEngine::Outcome outcome = engine.run(scene);
    ASSERT_TRUE(outcome.error);
    const std::optional<SceneError> expected = validate_scene(config, scene);
    ASSERT_TRUE(expected);
    EXPECT_EQ(outcome.error->code, "overlap");
    EXPECT_EQ(outcome.error->message, expected->message);
    EXPECT_EQ(outcome.error->body_id, expected->body_id);
    // The rejected scene is not remembered: the same scene is rejected again.
    EXPECT_TRUE(engine.run(scene).error);
}

TEST_F(AfterAValidLayout, AStrikerPlacedOnACoinIsRejected) {
    std::vector<Body> scene = layout;
    scene.push_back(striker(kStrikerId, layout[4].pos_px.x + 20.0, layout[4].pos_px.y));
    const ExactEngine::Outcome outcome = engine.run(scene);
    ASSERT_TRUE(outcome.error);
    EXPECT_EQ(outcome.error->code, "overlap");
    EXPECT_EQ(outcome.error->body_id, kStrikerId);
}

TEST(ExactValidation, KnownPairsSkipOnlyPairsOfTwoKnownBodies) {
    const PhysicsConfig config;
    // 1 and 2 overlap; so do 2 and 3.
    const std::vector<Body> scene{coin(1, 300.0, 300.0), coin(2, 320.0, 300.0),
                                  coin(3, 340.0, 300.0)};
    EXPECT_EQ(validate_scene(config, scene)->message, "body 2 overlaps body 1 by 8.000000 px");
    // Bodies 0 and 1 (ids 1 and 2) declared valid together: the first pair left is (2, 3).
    const auto error = validate_scene(config, scene, 1e-9, 0b011);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->body_id, 3);
    EXPECT_EQ(error->message, "body 3 overlaps body 2 by 8.000000 px");
    // All three known: nothing left to find.
    EXPECT_FALSE(validate_scene(config, scene, 1e-9, 0b111));
}

TEST(ExactValidation, KnownPairsDoNotSkipTheBodyByBodyChecks) {
    const PhysicsConfig config;
    const std::vector<Body> scene{coin(1, 300.0, 300.0), coin(1, 100.0, 100.0),
                                  coin(3, 300.0, 40.0)};
    const auto error = validate_scene(config, scene, 1e-9, 0b111);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "duplicate_id");
    const std::vector<Body> outside{coin(1, 300.0, 300.0), coin(3, 300.0, 40.0)};
    const auto outside_error = validate_scene(config, outside, 1e-9, 0b11);
    ASSERT_TRUE(outside_error);
    EXPECT_EQ(outside_error->code, "outside_cushions");
    EXPECT_EQ(outside_error->body_id, 3);
}

} // namespace
} // namespace carrom
