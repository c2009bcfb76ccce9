// Runs a scene with the exact engine or the fixed-step integrator, timing each run with the
// steady clock (tools may read clocks; common/ never does).

#include "sim_cli.hpp"

#include "invariants.hpp"

#include "carrom/exact_engine.hpp"
#include "carrom/fixed_step.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

namespace carrom::sim_cli {

namespace {

using Json = nlohmann::json;
using Clock = std::chrono::steady_clock;

double elapsed_us(Clock::time_point start) {
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

// Median and minimum of the per-run wall times, us.
void add_wall_times(Json& out, std::vector<double> times_us) {
    std::sort(times_us.begin(), times_us.end());
    const std::size_t n = times_us.size();
    const double median =
        n % 2 == 1 ? times_us[n / 2] : (times_us[n / 2 - 1] + times_us[n / 2]) / 2.0;
    out["runs"] = n;
    out["wall_time_us"] = median;
    out["wall_time_min_us"] = times_us.front();
}

RunOutput run_exact(const proto::SceneSpec& scene, const RunOptions& options) {
    SimOptions sim;
    sim.record_events = options.record_events || options.invariants;
    sim.record_trajectory = options.invariants;
    if (options.at_s) {
        sim.until_s = *options.at_s;
    }
    ExactEngine engine(scene.config);
    std::vector<double> times_us;
    ExactEngine::Outcome outcome;
    for (int run = 0; run < options.repeat; ++run) {
        const auto start = Clock::now();
        outcome = engine.run(scene.bodies, sim);
        times_us.push_back(elapsed_us(start));
        if (outcome.error) {
            const SceneError& e = *outcome.error;
            return {{}, proto::Error{e.code, e.message, e.field}};
        }
    }
    Json out = proto::sim_result_to_json(*outcome.result);
    out["integrator"] = "exact";
    if (options.invariants) {
        out["invariants"] = check_invariants(scene.config, *outcome.result);
    }
    if (!options.record_events) {
        out.erase("events");
    }
    add_wall_times(out, std::move(times_us));
    return {std::move(out), std::nullopt};
}

bool still_moving(const std::vector<Body>& bodies) {
    return std::any_of(bodies.begin(), bodies.end(), [](const Body& b) {
        return !b.pocketed && (b.vel_px_s.x != 0.0 || b.vel_px_s.y != 0.0);
    });
}

RunOutput run_fixed(const proto::SceneSpec& scene, const RunOptions& options) {
    FixedStepOptions fixed;
    fixed.frame_dt_s = options.frame_dt_s;
    fixed.substeps = options.substeps;
    fixed.record_events = options.record_events;
    if (options.at_s) {
        fixed.until_s = *options.at_s;
    }
    std::vector<double> times_us;
    FixedStepResult result;
    for (int run = 0; run < options.repeat; ++run) {
        const auto start = Clock::now();
        result = simulate_fixed_step(scene.config, scene.bodies, fixed);
        times_us.push_back(elapsed_us(start));
    }
    Json out{{"integrator", "fixed"},
             {"dt_s", options.frame_dt_s / options.substeps},
             {"substeps", options.substeps},
             {"end_time_s", result.end_time_s},
             {"truncated", result.truncated || (!options.at_s && still_moving(result.bodies))},
             {"bodies", proto::bodies_to_json(result.bodies)},
             {"pocketed", proto::pocketed_ids_to_json(result.bodies)},
             {"stats", {{"steps", result.steps}, {"events", result.events.size()}}}};
    if (options.record_events) {
        out["events"] = proto::events_to_json(result.events);
    }
    add_wall_times(out, std::move(times_us));
    return {std::move(out), std::nullopt};
}

} // namespace

RunOutput run_scene(const proto::SceneSpec& scene, const RunOptions& options) {
    RunOutput output = options.integrator == Integrator::Exact ? run_exact(scene, options)
                                                               : run_fixed(scene, options);
    if (!output.error && options.at_s) {
        output.document["at_s"] = *options.at_s;
    }
    return output;
}

} // namespace carrom::sim_cli
