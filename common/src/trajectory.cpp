#include "carrom/trajectory.hpp"

#include <algorithm>
#include <cmath>

namespace carrom {

double travel_factor_s(double damping_per_s, double dt_s) {
    // The limit at k = 0 is dt; a subnormal k gives dt too (e^(-k dt) rounds to 1 - k dt).
    if (damping_per_s == 0.0) {
        return dt_s;
    }
    return -std::expm1(-damping_per_s * dt_s) / damping_per_s;
}

std::vector<Body> state_at(const PhysicsConfig& config, const Trajectory& trajectory, double t_s) {
    t_s = std::max(t_s, 0.0);
    std::vector<Body> bodies = trajectory.initial;
    std::vector<double> since(bodies.size(), 0.0); // time each body's current segment began, s
    for (const Segment& seg : trajectory.segments) {
        if (seg.t_s > t_s) {
            break; // segments are in time order
        }
        const auto index = static_cast<std::size_t>(seg.index);
        Body& b = bodies[index];
        b.pos_px = seg.pos_px;
        b.vel_px_s = seg.vel_px_s;
        b.pocketed = seg.pocketed;
        since[index] = seg.t_s;
    }
    const double k = config.damping_per_s;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        Body& b = bodies[i];
        if (b.pocketed || (b.vel_px_s.x == 0.0 && b.vel_px_s.y == 0.0)) {
            continue;
        }
        const double dt = t_s - since[i];
        b.pos_px += b.vel_px_s * travel_factor_s(k, dt);
        b.vel_px_s *= std::exp(-k * dt);
    }
    return bodies;
}

} // namespace carrom
