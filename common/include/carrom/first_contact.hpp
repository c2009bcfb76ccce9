#pragma once
// The aim assist's question, answered by the exact engine: which piece does the striker touch
// first, where, and where does that piece go. Pure and deterministic (the engine's run of the
// scene, nothing else), so every client that holds the same board draws the same guide.

#include "carrom/body.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/vec2.hpp"

#include <optional>
#include <span>

namespace carrom {

struct FirstContact {
    int piece_id = -1;      // the body the striker touches first
    double t_s = 0.0;       // when, s after the start of the shot
    Vec2 striker_px{};      // the striker's centre at the contact
    Vec2 piece_px{};        // the piece's centre at the contact (it was at rest until then)
    Vec2 piece_vel_px_s{};  // the piece's velocity just after the contact, as the engine
                            // resolves it (a piece held by a cluster may get less than the
                            // two-disc impulse; zero if the contact does not move it)
    Vec2 piece_direction{}; // piece_vel_px_s as a unit vector; zero when the velocity is zero
    friend bool operator==(const FirstContact&, const FirstContact&) = default;
};

// Simulates `bodies` (a valid scene: the striker, kind Striker, moving; the pieces at rest) with
// `engine` and returns the striker's first disc-disc contact: nullopt when the striker touches no
// piece (it stops, or is pocketed, first; cushion contacts before the piece are followed), when
// the scene has no moving striker, or when the engine refuses the scene.
std::optional<FirstContact> first_contact(ExactEngine& engine, std::span<const Body> bodies);

} // namespace carrom
