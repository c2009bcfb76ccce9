// The summaries every run fills (pocket order, disc contacts per body) agree with the event list,
// and do not depend on whether events are recorded.

#include "carrom/exact_engine.hpp"
#include "carrom/scene.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <random>

namespace carrom {
namespace {

TEST(ExactSummary, PocketOrderAndContactCountsMatchTheEventsWithOrWithoutRecording) {
    const PhysicsConfig config;
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> x(baseline_x_min(config), baseline_x_max(config));
    std::uniform_real_distribution<double> angle(-2.6, -0.5);
    std::uniform_real_distribution<double> power(5.0, 25.0);
    ExactEngine recording(config);
    ExactEngine silent(config);
    int pocketed_total = 0;
    for (int shot = 0; shot < 64; ++shot) {
        std::vector<Body> scene = standard_layout(config);
        scene.push_back(make_striker(config, Baseline::Bottom, Shot{x(rng), angle(rng), power(rng)}));
        SimOptions with_events;
        with_events.record_events = true;
        SimOptions without_events;
        without_events.record_events = false;
        const SimResult a = *recording.run(scene, with_events).result;
        const SimResult b = *silent.run(scene, without_events).result;
        EXPECT_TRUE(b.events.empty());
        std::vector<int> order;
        std::vector<int> counts(scene.size(), 0);
        for (const Event& event : a.events) {
            if (event.kind == EventKind::Pocket) {
                order.push_back(event.a);
            } else if (event.kind == EventKind::Collision) {
                ++counts[static_cast<std::size_t>(event.a)]; // ids equal indices here
                ++counts[static_cast<std::size_t>(event.b)];
            }
        }
        EXPECT_EQ(a.pocket_order, order) << "shot " << shot;
        EXPECT_EQ(a.collision_counts, counts) << "shot " << shot;
        EXPECT_EQ(b.pocket_order, a.pocket_order) << "shot " << shot;
        EXPECT_EQ(b.collision_counts, a.collision_counts) << "shot " << shot;
        pocketed_total += static_cast<int>(order.size());
    }
    EXPECT_GT(pocketed_total, 0); // the shots exercised pocketing
}

TEST(ExactSummary, AStrikerThatMissesEverythingHasNoContacts) {
    const PhysicsConfig config;
    std::vector<Body> scene = standard_layout(config);
    // Straight along the baseline: it meets only cushions.
    scene.push_back(make_striker(config, Baseline::Bottom, Shot{300.0, 0.0, 10.0}));
    ExactEngine engine(config);
    const SimResult result = *engine.run(scene).result;
    EXPECT_EQ(result.collision_counts.back(), 0);
    EXPECT_EQ(result.collision_counts.size(), scene.size());
}

} // namespace
} // namespace carrom
