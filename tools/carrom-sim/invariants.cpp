#include "invariants.hpp"

#include "carrom/trajectory.hpp"

#include <algorithm>
#include <vector>

namespace carrom::sim_cli {

namespace {

struct Measures {
    double max_overlap_px = 0.0;
    double max_cushion_violation_px = 0.0;
    double kinetic_energy = 0.0; // 0.5 m v^2, mass * px^2 / s^2
};

Measures measure(const PhysicsConfig& config, const std::vector<Body>& bodies) {
    Measures m;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& a = bodies[i];
        if (a.pocketed) {
            continue;
        }
        const double r = config.radius(a.kind);
        const double lo = config.cushion_min(r);
        const double hi = config.cushion_max(r);
        for (double x : {a.pos_px.x, a.pos_px.y}) {
            m.max_cushion_violation_px = std::max({m.max_cushion_violation_px, lo - x, x - hi});
        }
        m.kinetic_energy += 0.5 * config.mass(a.kind) * length_squared(a.vel_px_s);
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            const Body& b = bodies[j];
            if (!b.pocketed) {
                const double reach = r + config.radius(b.kind);
                m.max_overlap_px = std::max(m.max_overlap_px, reach - length(b.pos_px - a.pos_px));
            }
        }
    }
    return m;
}

// Event times, each once, and the midpoints between consecutive ones, from t = 0.
std::vector<double> check_times(const SimResult& result) {
    std::vector<double> events{0.0};
    for (const Event& e : result.events) {
        if (e.t_s != events.back()) {
            events.push_back(e.t_s);
        }
    }
    std::vector<double> times;
    for (std::size_t i = 0; i < events.size() && times.size() < kMaxInvariantChecks; ++i) {
        if (i > 0) {
            times.push_back(0.5 * (events[i - 1] + events[i]));
        }
        times.push_back(events[i]);
    }
    return times;
}

} // namespace

nlohmann::json check_invariants(const PhysicsConfig& config, const SimResult& result) {
    const std::vector<double> times = check_times(result);
    double worst_overlap = 0.0;
    double worst_cushion = 0.0;
    double worst_increase = 0.0;
    double previous_energy = -1.0;
    for (double t : times) {
        const Measures m = measure(config, state_at(config, result.trajectory, t));
        worst_overlap = std::max(worst_overlap, m.max_overlap_px);
        worst_cushion = std::max(worst_cushion, m.max_cushion_violation_px);
        if (previous_energy > 0.0) {
            worst_increase =
                std::max(worst_increase, (m.kinetic_energy - previous_energy) / previous_energy);
        }
        previous_energy = m.kinetic_energy;
    }
    // Rounding alone moves the energy by a few ulps; anything above 1e-12 is a real increase.
    return {{"checked_times", times.size()},
            {"max_overlap_px", worst_overlap},
            {"max_cushion_violation_px", worst_cushion},
            {"energy_increased", worst_increase > 1e-12},
            {"max_energy_increase_rel", worst_increase}};
}

} // namespace carrom::sim_cli
