#pragma once
// carrom-sim: the options of one run and the function that runs a decoded scene with them.

#include "carrom/proto/scene_json.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace carrom::sim_cli {

enum class Integrator { Exact, Fixed };

struct RunOptions {
    Integrator integrator = Integrator::Exact;
    double frame_dt_s = 1.0 / 60.0; // fixed: one frame
    int substeps = 1;               // fixed: steps per frame
    std::optional<double> at_s;     // report the state at this time instead of the final one
    int repeat = 1;                 // runs; wall time is reported as median and minimum
    bool record_events = true;
    bool invariants = false; // exact: check overlap, cushions and energy at every event
};

// Runs the scene and returns the output document, or an error (exit code 2).
struct RunOutput {
    nlohmann::json document;
    std::optional<proto::JsonError> error;
};
RunOutput run_scene(const proto::SceneSpec& scene, const RunOptions& options);

} // namespace carrom::sim_cli
