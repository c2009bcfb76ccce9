#pragma once
// Helpers shared by the physics tests: scene building and the invariants checked after every
// event (no overlap beyond 1e-6 px, kinetic energy never increases, every body inside the
// cushions or pocketed).

#include "carrom/exact_engine.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace carrom::test {

// True when both doubles have the same bits (determinism tests compare results bit for bit).
inline bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

inline Body coin(int id, double x, double y, double vx = 0.0, double vy = 0.0,
                 BodyKind kind = BodyKind::Black) {
    return {id, kind, {x, y}, {vx, vy}, false};
}

inline Body striker(int id, double x, double y, double vx = 0.0, double vy = 0.0) {
    return {id, BodyKind::Striker, {x, y}, {vx, vy}, false};
}

inline double kinetic_energy(const PhysicsConfig& config, const std::vector<Body>& bodies) {
    double sum = 0.0;
    for (const Body& b : bodies) {
        if (!b.pocketed) {
            sum += 0.5 * config.mass(b.kind) * length_squared(b.vel_px_s);
        }
    }
    return sum;
}

// Largest overlap of any two unpocketed bodies, px (0 when none overlap).
inline double max_overlap(const PhysicsConfig& config, const std::vector<Body>& bodies) {
    double worst = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        for (std::size_t j = i + 1; j < bodies.size(); ++j) {
            if (bodies[i].pocketed || bodies[j].pocketed) {
                continue;
            }
            const double reach = config.radius(bodies[i].kind) + config.radius(bodies[j].kind);
            worst = std::max(worst, reach - length(bodies[j].pos_px - bodies[i].pos_px));
        }
    }
    return worst;
}

// Largest distance by which any unpocketed centre lies outside its cushion limits, px.
inline double max_cushion_violation(const PhysicsConfig& config, const std::vector<Body>& bodies) {
    double worst = 0.0;
    for (const Body& b : bodies) {
        if (b.pocketed) {
            continue;
        }
        const double r = config.radius(b.kind);
        for (double v : {b.pos_px.x, b.pos_px.y}) {
            worst = std::max({worst, config.cushion_min(r) - v, v - config.cushion_max(r)});
        }
    }
    return worst;
}

struct InvariantReport {
    double max_overlap_px = 0.0;
    double max_cushion_violation_px = 0.0;
    double max_energy_gain = 0.0; // largest increase of kinetic energy between checks
    int events = 0;
    bool truncated = false;
    bool all_at_rest = false;
};

// Runs the scene with a trajectory and checks the invariants just after every event time.
inline InvariantReport run_checked(const PhysicsConfig& config, const std::vector<Body>& scene) {
    SimOptions options;
    options.record_trajectory = true;
    const SimulateResult sim = simulate_exact(config, scene, options);
    EXPECT_FALSE(sim.error.has_value()) << (sim.error ? sim.error->message : "");
    InvariantReport report;
    report.events = sim.result.stats.events;
    report.truncated = sim.result.truncated;
    double previous_energy = kinetic_energy(config, scene);
    for (const Segment& seg : sim.result.trajectory.segments) {
        const std::vector<Body> state = state_at(config, sim.result.trajectory, seg.t_s);
        report.max_overlap_px = std::max(report.max_overlap_px, max_overlap(config, state));
        report.max_cushion_violation_px =
            std::max(report.max_cushion_violation_px, max_cushion_violation(config, state));
        const double energy = kinetic_energy(config, state);
        report.max_energy_gain = std::max(report.max_energy_gain, energy - previous_energy);
        previous_energy = energy;
    }
    report.all_at_rest = true;
    for (const Body& b : sim.result.bodies) {
        report.all_at_rest = report.all_at_rest && b.vel_px_s == Vec2{};
    }
    return report;
}

inline void expect_invariants(const InvariantReport& r, int max_events) {
    EXPECT_LE(r.max_overlap_px, 1e-6);
    EXPECT_LE(r.max_cushion_violation_px, 1e-6);
    EXPECT_LE(r.max_energy_gain, 1e-9);
    EXPECT_FALSE(r.truncated);
    EXPECT_TRUE(r.all_at_rest);
    EXPECT_LE(r.events, max_events);
}

} // namespace carrom::test
