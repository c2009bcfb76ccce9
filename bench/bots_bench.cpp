// Bot search speed (issue 7): candidate shots the greedy strategy simulates and judges per second
// on one core, on the standard layout (the break: every candidate is a full break simulation
// plus the rules) and on a sparse mid-game board. Target: >= 50,000 candidates/s on the
// standard layout. items_per_second is candidates per second:
//   carrom_bench --benchmark_filter=Greedy --benchmark_repetitions=5

#include "benchmark_bots.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace carrom;
using carrom::bench::standard_match;

// The standard layout with every other piece off the board (9 left, the queen among them).
rules::MatchState sparse_match() {
    rules::MatchState state = standard_match();
    state.break_done = true;
    for (Body& body : state.bodies) {
        if (body.id % 2 == 1) {
            body.pocketed = true;
            state.pocketed.push_back(rules::PocketedPiece{body.id, body.kind, 1, 0});
        }
    }
    return state;
}

void run_greedy(benchmark::State& bench, const rules::MatchState& state) {
    bots::GreedyStrategy greedy(bench::greedy_options());
    const bots::DecisionBudget budget = bench::decision_budget();
    std::int64_t candidates = 0;
    for (auto _ : bench) {
        const Shot shot = greedy.choose_shot(state, 0, budget);
        benchmark::DoNotOptimize(shot);
        candidates += greedy.last_decision().candidates;
    }
    bench.SetItemsProcessed(candidates);
    bench.counters["candidates_per_decision"] =
        static_cast<double>(candidates) / static_cast<double>(bench.iterations());
}

void BotsGreedyStandardLayout(benchmark::State& bench) {
    run_greedy(bench, standard_match());
}
BENCHMARK(BotsGreedyStandardLayout)->Unit(benchmark::kMillisecond);

void BotsGreedySparseBoard(benchmark::State& bench) {
    run_greedy(bench, sparse_match());
}
BENCHMARK(BotsGreedySparseBoard)->Unit(benchmark::kMillisecond);

} // namespace
