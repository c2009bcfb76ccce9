#pragma once
// carrom-sim --invariants: checks a recorded exact simulation at every event time and halfway
// between consecutive event times: the largest overlap of two unpocketed bodies, the largest
// distance of a centre outside its cushion range, and whether the kinetic energy ever grew.

#include "carrom/config.hpp"
#include "carrom/exact_engine.hpp"

#include <nlohmann/json.hpp>

namespace carrom::sim_cli {

// At most this many instants are checked (the first ones).
inline constexpr std::size_t kMaxInvariantChecks = 20000;

// {"checked_times", "max_overlap_px", "max_cushion_violation_px", "energy_increased",
//  "max_energy_increase_rel"}. Needs result.trajectory and result.events.
nlohmann::json check_invariants(const PhysicsConfig& config, const SimResult& result);

} // namespace carrom::sim_cli
