#include "carrom/trajectory.hpp"
#include "carrom/det_math.hpp"

#include "carrom/trajectory_cursor.hpp"

#include <cmath>

namespace carrom {

double travel_factor_s(double damping_per_s, double dt_s) {
    // The limit at k = 0 is dt; a subnormal k gives dt too (e^(-k dt) rounds to 1 - k dt).
    if (damping_per_s == 0.0) {
        return dt_s;
    }
    return -det::expm1(-damping_per_s * dt_s) / damping_per_s;
}

std::vector<Body> state_at(const PhysicsConfig& config, const Trajectory& trajectory, double t_s) {
    // A fresh cursor replays the segments from the first one: one copy of the motion's formula.
    TrajectoryCursor cursor;
    return cursor.at(config, trajectory, t_s);
}

} // namespace carrom
