// carrom-engine-runs: runs the exact engine on the shots of the benchmarks a given number of
// times and prints one line, for measurements that the shared machine's drifting speed does not
// blur (docs/physics.md, "Speed"):
//   - instructions per shot or per bot candidate: the difference of two runs under valgrind
//     (scripts/engine_instructions.sh);
//   - bit-identity of an engine change: the same result hash before and after.
// Scenes: `break` (the standard break), `random` (the physics benchmark's 1,024 random full
// shots in turn, or with --shot K only shot K): the line gives the runs, the events of the timed
// runs, a ResultHash of every event and final state of a first, untimed pass, and the wall time per
// run, us. `greedy` (built with the bots library): runs are decisions of the hard greedy bot on the
// standard layout, as in BotsGreedyStandardLayout; the line gives the candidates and the wall time
// per candidate.

#include "benchmark_shots.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/result_hash.hpp"

#include "benchmark_bots.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace carrom;
using Clock = std::chrono::steady_clock;

double elapsed_us(Clock::time_point start) {
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

int run_shots(const PhysicsConfig& config, const char* name,
              const std::vector<std::vector<Body>>& shots, int runs) {
    ExactEngine engine(config);
    SimOptions options;
    options.record_events = true;
    ResultHash hash;
    for (const auto& shot : shots) {
        const ExactEngine::Outcome outcome = engine.run(shot, options);
        if (outcome.error || outcome.result == nullptr) {
            std::fprintf(stderr, "carrom-engine-runs: a benchmark shot was rejected\n");
            return 1;
        }
        hash.add(*outcome.result);
    }
    // The timed runs record no events, as in the benchmarks.
    options.record_events = false;
    long events = 0;
    const Clock::time_point start = Clock::now();
    for (int run = 0; run < runs; ++run) {
        const auto& shot = shots[static_cast<std::size_t>(run) % shots.size()];
        const SimResult* result = engine.run(shot, options).result;
        events += result != nullptr ? result->stats.events : 0;
    }
    const double us = elapsed_us(start);
    std::printf("scene %s runs %d events %ld hash %016llx us_per_shot %.3f\n", name, runs, events,
                static_cast<unsigned long long>(hash.value()), us / runs);
    return 0;
}

// The decisions of bench/bots_bench.cpp's BotsGreedyStandardLayout.
int run_greedy(int decisions) {
    const rules::MatchState state = bench::standard_match();
    bots::GreedyStrategy greedy(bench::greedy_options());
    const bots::DecisionBudget budget = bench::decision_budget();
    long candidates = 0;
    const Clock::time_point start = Clock::now();
    for (int decision = 0; decision < decisions; ++decision) {
        greedy.choose_shot(state, 0, budget);
        candidates += greedy.last_decision().candidates;
    }
    const double us = elapsed_us(start);
    std::printf("scene greedy runs %d candidates %ld us_per_candidate %.3f\n", decisions,
                candidates, candidates > 0 ? us / static_cast<double>(candidates) : 0.0);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"carrom-engine-runs: the benchmarks' shots, for instruction counts and result "
                 "hashes (docs/physics.md)"};
    enum class Scene { Break, Random, Greedy };
    std::map<std::string, Scene> scenes{
        {"break", Scene::Break}, {"random", Scene::Random}, {"greedy", Scene::Greedy}};
    Scene scene = Scene::Break;
    int runs = 1;
    app.add_option("--scene", scene,
                   "break (the standard break), random (1,024 random shots) or greedy (bot "
                   "decisions)")
        ->transform(CLI::CheckedTransformer(scenes, CLI::ignore_case));
    app.add_option("--runs", runs, "shots to simulate (the random list is cycled), or decisions")
        ->check(CLI::Range(1, 100000000));
    int only = -1;
    app.add_option("--shot", only, "random: repeat only this shot of the list (0 to 1023)")
        ->check(CLI::Range(0, 1023));
    CLI11_PARSE(app, argc, argv);
    if (only >= 0 && scene != Scene::Random) {
        std::fprintf(stderr, "carrom-engine-runs: --shot applies only to --scene random\n");
        return 2;
    }

    const PhysicsConfig config;
    switch (scene) {
    case Scene::Break:
        return run_shots(config, "break", {bench::break_scene(config)}, runs);
    case Scene::Random: {
        std::vector<std::vector<Body>> shots = bench::random_shots(config, 1024);
        if (only >= 0) {
            shots = {shots[static_cast<std::size_t>(only)]};
        }
        return run_shots(config, "random", shots, runs);
    }
    case Scene::Greedy:
        return run_greedy(runs);
    }
    return 2;
}
