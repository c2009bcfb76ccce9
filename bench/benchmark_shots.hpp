#pragma once
// The shots of the physics benchmarks, shared by carrom_bench (physics_bench.cpp) and
// carrom-engine-runs (engine_runs/main.cpp) so that both measure the same work.

#include "carrom/scene.hpp"

#include <numbers>
#include <random>
#include <vector>

namespace carrom::bench {

// The standard layout plus the striker: centred, straight up, full power, bottom baseline.
inline std::vector<Body> break_scene(const PhysicsConfig& config) {
    std::vector<Body> bodies = standard_layout(config);
    bodies.push_back(
        make_striker(config, Baseline::Bottom, Shot{300.0, -std::numbers::pi / 2.0, 25.0}));
    return bodies;
}

// A fixed list of random full shots from the bottom baseline: x over the baseline range, angle
// within 60 degrees of straight up, power in [5, 25].
inline std::vector<std::vector<Body>> random_shots(const PhysicsConfig& config, int count) {
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> x(baseline_x_min(config), baseline_x_max(config));
    std::uniform_real_distribution<double> angle(-std::numbers::pi / 2.0 - std::numbers::pi / 3.0,
                                                 -std::numbers::pi / 2.0 + std::numbers::pi / 3.0);
    std::uniform_real_distribution<double> power(5.0, 25.0);
    std::vector<std::vector<Body>> shots;
    const std::vector<Body> layout = standard_layout(config);
    for (int i = 0; i < count; ++i) {
        std::vector<Body> bodies = layout;
        const double sx = x(rng);
        const double sa = angle(rng);
        const double sp = power(rng);
        bodies.push_back(make_striker(config, Baseline::Bottom, Shot{sx, sa, sp}));
        shots.push_back(std::move(bodies));
    }
    return shots;
}

} // namespace carrom::bench
