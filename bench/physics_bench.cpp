// Physics speed targets (issue 3): the exact engine on the standard break (median <= 10 us per
// full shot) and on random full shots (>= 100,000 shots/s on one core), and the fixed-step
// integrator on the break for scale. Every benchmark also reports "min" over repetitions:
//   carrom_bench --benchmark_filter=Physics --benchmark_repetitions=10

#include "benchmark_shots.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/fixed_step.hpp"
#include "carrom/scene.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

namespace {

using namespace carrom;
using carrom::bench::break_scene;
using carrom::bench::random_shots;

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
