#pragma once
// A recorded trajectory: the initial bodies plus one segment per body per velocity change.
// Between segments a body follows the damped free motion
//   p(t) = p0 + v0 (1 - e^(-k (t - t0))) / k,   v(t) = v0 e^(-k (t - t0)).

#include "carrom/body.hpp"
#include "carrom/config.hpp"

#include <span>
#include <vector>

namespace carrom {

// From t_s on, body `index` (into the initial body list) moves from pos_px with vel_px_s, or is
// pocketed. Segments are ordered by time.
struct Segment {
    double t_s = 0.0;
    int index = 0;
    Vec2 pos_px{};
    Vec2 vel_px_s{};
    bool pocketed = false;
};

struct Trajectory {
    std::vector<Body> initial;
    std::vector<Segment> segments;
};

// Position after dt_s of damped free motion: distance factor s = (1 - e^(-k dt)) / k, s.
double travel_factor_s(double damping_per_s, double dt_s);

// The state of every body at time t_s (clamped to t >= 0), same order as trajectory.initial.
std::vector<Body> state_at(const PhysicsConfig& config, const Trajectory& trajectory, double t_s);

} // namespace carrom
