#pragma once
// The seed's frame loop as a fixed-step integrator of the same model, used only to compare
// against the exact engine (docs/physics-report.md). Per step of dt = frame_dt_s / substeps:
// move p += v dt; damp v *= e^(-k dt); stop below the stop speed; cushions clamp and reflect the
// normal velocity scaled by the cushion restitution; pocket when the centre is inside a pocket
// circle; then every overlapping, approaching pair gets the seed's impulse (with e) and is
// pushed apart equally by overlap / 2 + 0.5 px, as the seed does.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/event.hpp"

#include <limits>
#include <span>
#include <vector>

namespace carrom {

struct FixedStepOptions {
    double frame_dt_s = 1.0 / 60.0; // one frame
    int substeps = 1;               // steps per frame; dt = frame_dt_s / substeps
    double max_time_s = 120.0;      // safety bound on simulated time
    // Stop the simulation at this time (bodies may still move).
    double until_s = std::numeric_limits<double>::infinity();
    bool record_events = true;
};

struct FixedStepResult {
    std::vector<Body> bodies; // same order and ids as the input
    std::vector<Event> events;
    double end_time_s = 0.0;
    long steps = 0;
    // The work bound was reached (2^26 pair tests, at most max(2^26 / (n (n - 1) / 2), 1) steps
    // for n bodies): the bodies are left as they were, possibly moving.
    bool truncated = false;
};

FixedStepResult simulate_fixed_step(const PhysicsConfig& config, std::span<const Body> bodies,
                                    const FixedStepOptions& options);

} // namespace carrom
