// The engine's results, pinned: a hash of every event and final state of the break and of 512
// random shots on the standard layout. Speed work on the engine must keep results bit for bit
// (docs/physics.md, "Speed"), because the bot measurements of docs/bots.md were taken with them.
// If a change alters results on purpose, update the constants below (and the break's hash in
// bench/engine_runs/CMakeLists.txt) and re-run the bots report
// (the command is in docs/bots.md).

#include "carrom/exact_engine.hpp"
#include "carrom/result_hash.hpp"
#include "carrom/scene.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace carrom {
namespace {

// A double in [lo, hi) from the generator's raw output (whose sequence the standard fixes).
double draw(std::mt19937_64& rng, double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(rng() >> 11U) * 0x1.0p-53;
}

TEST(ExactPinnedResults, TheBreakGivesThePinnedEventsAndFinalState) {
    const PhysicsConfig config;
    std::vector<Body> scene = standard_layout(config);
    scene.push_back(
        make_striker(config, Baseline::Bottom, Shot{300.0, -std::numbers::pi / 2.0, 25.0}));
    ExactEngine engine(config);
    const ExactEngine::Outcome run = engine.run(scene);
    ASSERT_FALSE(run.error.has_value());
    ResultHash hash;
    hash.add(*run.result);
    EXPECT_EQ(run.result->events.size(), 77U);
    EXPECT_EQ(hash.value(), 0x41f5cfe5483d391fULL) << std::hex << "actual 0x" << hash.value();
}

TEST(ExactPinnedResults, RandomShotsGiveThePinnedEventsAndFinalStates) {
    const PhysicsConfig config;
    const std::vector<Body> layout = standard_layout(config);
    std::mt19937_64 rng(20261122);
    ExactEngine engine(config);
    ResultHash hash;
    for (int shot = 0; shot < 512; ++shot) {
        std::vector<Body> scene = layout;
        const Shot s{draw(rng, baseline_x_min(config), baseline_x_max(config)),
                     -std::numbers::pi / 2.0 + draw(rng, -1.0, 1.0), draw(rng, 5.0, 25.0)};
        scene.push_back(make_striker(config, Baseline::Bottom, s));
        const ExactEngine::Outcome run = engine.run(scene);
        ASSERT_FALSE(run.error.has_value()) << "shot " << shot;
        hash.add(*run.result);
    }
    EXPECT_EQ(hash.value(), 0x872979a76d58061bULL) << std::hex << "actual 0x" << hash.value();
}

} // namespace
} // namespace carrom
