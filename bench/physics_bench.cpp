// Physics speed targets (issue 3): the exact engine on the standard break (median <= 10 us per
// full shot) and on random full shots (>= 100,000 shots/s on one core), and the fixed-step
// integrator on the break for scale. Every benchmark also reports "min" over repetitions:
//   carrom_bench --benchmark_filter=Physics --benchmark_repetitions=10

#include "carrom/exact_engine.hpp"
#include "carrom/fixed_step.hpp"
#include "carrom/scene.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <numbers>
#include <random>
#include <vector>

namespace {

using namespace carrom;

// The standard layout plus the striker: centred, straight up, full power, bottom baseline.
std::vector<Body> break_scene(const PhysicsConfig& config) {
    std::vector<Body> bodies = standard_layout(config);
    bodies.push_back(
        make_striker(config, Baseline::Bottom, Shot{300.0, -std::numbers::pi / 2.0, 25.0}));
    return bodies;
}

// A fixed list of random full shots from the bottom baseline: x over the baseline range, angle
// within 60 degrees of straight up, power in [5, 25].
std::vector<std::vector<Body>> random_shots(const PhysicsConfig& config, int count) {
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

void add_min_statistic(benchmark::internal::Benchmark* b) {
    b->ComputeStatistics(
        "min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
}

void PhysicsExactBreak(benchmark::State& state) {
    const PhysicsConfig config;
    const std::vector<Body> bodies = break_scene(config);
    ExactEngine engine(config);
    SimOptions options;
    options.record_events = state.range(0) != 0;
    int events = 0;
    for (auto _ : state) {
        const auto outcome = engine.run(bodies, options);
        benchmark::DoNotOptimize(outcome.result);
        events = outcome.result->stats.events;
    }
    state.counters["events"] = events;
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(PhysicsExactBreak)
    ->ArgName("record_events")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMicrosecond)
    ->Apply(add_min_statistic);

void PhysicsExactRandomShots(benchmark::State& state) {
    const PhysicsConfig config;
    const auto shots = random_shots(config, 1024);
    ExactEngine engine(config);
    SimOptions options;
    options.record_events = false;
    std::size_t next = 0;
    long events = 0;
    for (auto _ : state) {
        const auto outcome = engine.run(shots[next], options);
        benchmark::DoNotOptimize(outcome.result);
        events += outcome.result->stats.events;
        next = (next + 1) % shots.size();
    }
    state.counters["events_per_shot"] =
        static_cast<double>(events) / static_cast<double>(state.iterations());
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(PhysicsExactRandomShots)->Unit(benchmark::kMicrosecond)->Apply(add_min_statistic);

// Fixed-step integrator on the break; the argument is the number of steps per second.
void PhysicsFixedBreak(benchmark::State& state) {
    const PhysicsConfig config;
    const std::vector<Body> bodies = break_scene(config);
    FixedStepOptions options;
    options.frame_dt_s = 1.0 / static_cast<double>(state.range(0));
    options.record_events = false;
    for (auto _ : state) {
        auto result = simulate_fixed_step(config, bodies, options);
        benchmark::DoNotOptimize(result.bodies.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(PhysicsFixedBreak)
    ->ArgName("steps_per_s")
    ->Arg(60)
    ->Arg(960)
    ->Unit(benchmark::kMicrosecond)
    ->Apply(add_min_statistic);

} // namespace
