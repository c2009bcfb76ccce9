#pragma once
// The physical model of the board in one plain struct. Units: px, s, px/s, mass in coin masses.
// Defaults reproduce the seed game's feel (600 px board, friction 0.985 per 1/60 s frame, ...);
// see docs/physics.md for where and why the model differs from the seed's frame loop.

#include "carrom/body.hpp"
#include "carrom/det_math.hpp"
#include "carrom/vec2.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace carrom {

struct PhysicsConfig {
    double board_size_px = 600.0;    // outer size of the square board
    double frame_px = 35.0;          // cushion face distance from each board edge
    double coin_radius_px = 14.0;    // black, white and queen
    double striker_radius_px = 18.0; //
    double coin_mass = 1.0;          //
    double striker_mass = 2.0;       //
    // Linear damping rate k in dv/dt = -k v, 1/s. The seed multiplies velocity by 0.985 every
    // 1/60 s frame, so k = 60 ln(1 / 0.985) = 0.906818... 1/s.
    double damping_per_s = 60.0 * det::log(1.0 / 0.985);
    double stop_speed_px_s = 6.0;     // a body stops when its speed falls to this (0.1 px/frame)
    double cushion_restitution = 0.8; // normal velocity scale at a cushion
    double disc_restitution = 0.9;    // coefficient e between two discs
    // Remedy for inelastic collapse: a contact whose approach speed is below this is plastic
    // (restitution 0). See docs/physics.md, "Simultaneous and stiff contacts".
    double restitution_floor_px_s = 2.0;
    double pocket_radius_px = 22.0;       // pocket circles touch both cushion faces
    double max_power = 25.0;              // shot power range [0, max_power], seed px/frame
    double power_to_speed = 60.0;         // px/s per unit of power (the seed's frames per second)
    double baseline_offset_px = 80.0;     // baseline y distance from the near board edge
    double baseline_end_margin_px = 60.0; // baseline x range: frame + margin + striker radius
    int max_events = 200000;              // hard safety bound per simulation

    friend bool operator==(const PhysicsConfig&, const PhysicsConfig&) = default;

    double radius(BodyKind kind) const {
        return kind == BodyKind::Striker ? striker_radius_px : coin_radius_px;
    }
    double mass(BodyKind kind) const {
        return kind == BodyKind::Striker ? striker_mass : coin_mass;
    }
    // Centres of bodies of radius r stay in [cushion_min(r), cushion_max(r)] on both axes.
    double cushion_min(double r) const { return frame_px + r; }
    double cushion_max(double r) const { return board_size_px - frame_px - r; }
    Vec2 centre() const { return {board_size_px / 2.0, board_size_px / 2.0}; }
    // Pocket centres: top-left, top-right, bottom-left, bottom-right.
    std::array<Vec2, 4> pocket_centres() const {
        const double lo = frame_px + pocket_radius_px;
        const double hi = board_size_px - lo;
        return {Vec2{lo, lo}, Vec2{hi, lo}, Vec2{lo, hi}, Vec2{hi, hi}};
    }
};

// A field that makes a config unusable (non-finite, non-positive, out of range).
struct ConfigError {
    std::string field;
    std::string message;
};

// Checks every field; returns the first problem found, or nothing.
std::optional<ConfigError> validate_config(const PhysicsConfig& config);

} // namespace carrom
