// carrom-engine-runs: runs the exact engine on the shots of the physics benchmarks (the standard
// break, or the benchmark's 1,024 random full shots in turn) a given number of times, then
// prints one line: the scene, the runs, the events of the timed runs, an FNV-1a hash of every
// event and final state of a first, untimed pass, and the wall time per timed run, us. For
// measurements that the shared machine's drifting speed does not blur:
//   - instructions per shot: the difference of two runs under valgrind
//     (scripts/engine_instructions.sh);
//   - bit-identity of an engine change: the same hash before and after.
// See docs/physics.md, "Speed".

#include "benchmark_shots.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/result_hash.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    using namespace carrom;
    CLI::App app{"carrom-engine-runs: the physics benchmarks' shots, for instruction counts and "
                 "result hashes (docs/physics.md)"};
    enum class Scene { Break, Random };
    const std::map<std::string, Scene> scenes{{"break", Scene::Break}, {"random", Scene::Random}};
    Scene scene = Scene::Break;
    int runs = 1;
    app.add_option("--scene", scene, "break (the standard break) or random (1,024 random shots)")
        ->transform(CLI::CheckedTransformer(scenes, CLI::ignore_case));
    app.add_option("--runs", runs, "shots to simulate (the random list is cycled)")
        ->check(CLI::Range(1, 100000000));
    CLI11_PARSE(app, argc, argv);

    const PhysicsConfig config;
    const bool is_break = scene == Scene::Break;
    const auto shots = is_break ? std::vector<std::vector<Body>>{bench::break_scene(config)}
                                : bench::random_shots(config, 1024);
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
    const auto start = std::chrono::steady_clock::now();
    for (int run = 0; run < runs; ++run) {
        const auto& shot = shots[static_cast<std::size_t>(run) % shots.size()];
        const SimResult* result = engine.run(shot, options).result;
        events += result != nullptr ? result->stats.events : 0;
    }
    const std::chrono::duration<double, std::micro> elapsed =
        std::chrono::steady_clock::now() - start;
    std::printf("scene %s runs %d events %ld hash %016llx us_per_shot %.3f\n",
                is_break ? "break" : "random", runs, events,
                static_cast<unsigned long long>(hash.value()), elapsed.count() / runs);
    return 0;
}
