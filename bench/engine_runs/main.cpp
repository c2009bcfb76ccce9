// carrom-engine-runs: runs the exact engine on the shots of the physics benchmarks (the standard
// break, or the benchmark's 1,024 random full shots in turn) a given number of times, then
// prints one line: the scene, the runs, the events of the timed runs, an FNV-1a hash of every
// event and final state of a first, untimed pass, and the wall time per timed run, us. For
// measurements that the shared machine's drifting speed does not blur:
//   - instructions per shot: the difference of two runs under valgrind
//     (scripts/engine_instructions.sh);
//   - bit-identity of an engine change: the same hash before and after.
// See docs/physics.md, "Speed".

#include "carrom/exact_engine.hpp"
#include "carrom/scene.hpp"

#include <CLI/CLI.hpp>

#include <bit>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace carrom;

// The shots of bench/physics_bench.cpp, drawn the same way.
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

std::vector<std::vector<Body>> break_shot(const PhysicsConfig& config) {
    std::vector<Body> bodies = standard_layout(config);
    bodies.push_back(
        make_striker(config, Baseline::Bottom, Shot{300.0, -std::numbers::pi / 2.0, 25.0}));
    return {bodies};
}

// FNV-1a over the bits of everything a run reports.
struct ResultHash {
    std::uint64_t value = 1469598103934665603ULL;
    void add(std::uint64_t word) {
        for (int byte = 0; byte < 8; ++byte) {
            value ^= (word >> (8 * byte)) & 0xFFU;
            value *= 1099511628211ULL;
        }
    }
    void add(double x) { add(std::bit_cast<std::uint64_t>(x)); }
    void add(int x) { add(static_cast<std::uint64_t>(static_cast<std::uint32_t>(x))); }
    void add(const SimResult& r) {
        for (const Event& e : r.events) {
            add(e.t_s);
            add(static_cast<int>(e.kind));
            add(e.a);
            add(e.b);
            add(e.impulse);
            add(e.pos_px.x);
            add(e.pos_px.y);
        }
        for (const Body& b : r.bodies) {
            add(b.pos_px.x);
            add(b.pos_px.y);
            add(b.vel_px_s.x);
            add(b.vel_px_s.y);
            add(b.pocketed ? 1 : 0);
        }
        add(r.end_time_s);
        for (int id : r.pocket_order) {
            add(id);
        }
    }
};

} // namespace

int main(int argc, char** argv) {
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
    const auto shots = is_break ? break_shot(config) : random_shots(config, 1024);
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
                static_cast<unsigned long long>(hash.value), elapsed.count() / runs);
    return 0;
}
