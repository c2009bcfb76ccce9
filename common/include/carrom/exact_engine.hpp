#pragma once
// The authoritative physics: an exact, event-driven engine. It jumps from event to event
// (disc-disc contact, cushion contact, pocket entry, stop), computing each event's time in
// closed form, so the result does not depend on any time step and nothing can tunnel.
// Deterministic: no clocks, no global state, no threads; the same input gives bit-identical
// output on the same build. See docs/physics.md.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/event.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace carrom {

struct SimOptions {
    bool record_events = true;      // fill SimResult::events
    bool record_trajectory = false; // fill SimResult::trajectory (for streaming and state_at)
    // Stop the simulation at this time and report the state then (bodies may still move).
    double until_s = std::numeric_limits<double>::infinity();
};

struct SimStats {
    int events = 0;          // events processed (collisions count once per contact)
    int contact_rounds = 0;  // simultaneous-contact solves
    int collapse_solves = 0; // contact groups resolved plastically to end a zero-time cascade
    int pair_tests = 0;      // pair predictions that reached the quadratic solve
};

struct SimResult {
    std::vector<Body> bodies;  // final state, same order and ids as the input
    std::vector<Event> events; // in time order; simultaneous ones in a fixed order
    Trajectory trajectory;     // when requested
    double end_time_s = 0.0;   // time of the last event (or until_s)
    // max_events or the work bound (2^23 pair tests, docs/physics.md) reached: the remaining
    // bodies were stopped in place.
    bool truncated = false;
    SimStats stats;
    // Filled whatever SimOptions::record_events says (cheap summaries for callers that need
    // no event list, such as the rules inside a bot's search):
    std::vector<int> pocket_order;     // ids of pocketed bodies, in the order they went in
    std::vector<int> collision_counts; // per body, input order: disc-disc contacts it had
};

// Reusable engine: keeps its buffers between runs, so bots can simulate many shots without
// allocating. Not thread-safe; use one per thread.
class ExactEngine {
public:
    explicit ExactEngine(const PhysicsConfig& config);
    ~ExactEngine();
    ExactEngine(const ExactEngine&) = delete;
    ExactEngine& operator=(const ExactEngine&) = delete;

    // Simulates until every body is at rest or pocketed (or options.until_s). The scene must pass
    // validate_scene; run() checks and returns the error instead of simulating otherwise.
    struct Outcome {
        std::optional<SceneError> error;
        const SimResult* result = nullptr; // valid until the next run() on this engine
    };
    Outcome run(std::span<const Body> bodies, const SimOptions& options = {});

    const PhysicsConfig& config() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// One-shot convenience wrapper around ExactEngine.
struct SimulateResult {
    std::optional<SceneError> error;
    SimResult result;
};
SimulateResult simulate_exact(const PhysicsConfig& config, std::span<const Body> bodies,
                              const SimOptions& options = {});

} // namespace carrom
