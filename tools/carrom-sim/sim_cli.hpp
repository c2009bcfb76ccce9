#pragma once
// carrom-sim: the options of one run and the function that runs a decoded scene with them.

#include "carrom/proto/scene_json.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>

namespace carrom::sim_cli {

// The exit code of a run whose input (scene, journal, frame log, options) was refused.
inline constexpr int kExitBadInput = 2;

// One JSON document on one line (or indented by 2 when pretty), invalid UTF-8 replaced.
inline void print_json(std::ostream& out, const nlohmann::json& j, bool pretty) {
    out << j.dump(pretty ? 2 : -1, ' ', false, nlohmann::json::error_handler_t::replace) << '\n';
}

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
    std::optional<proto::Error> error;
};
RunOutput run_scene(const proto::SceneSpec& scene, const RunOptions& options);

} // namespace carrom::sim_cli
