#pragma once
// Where strikers go and where returned pieces go.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/rules/rule_error.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"

#include <optional>
#include <span>

namespace carrom::rules {

// The striker body (id kStrikerId) for a shot from a side. shot.x_px is the position along the
// baseline: x for the bottom and top sides, y for the left and right ones (baselines at
// baseline_offset_px from the near edge). Does not validate the shot.
Body striker_for(const PhysicsConfig& physics, Side side, const Shot& shot);

// Checks a shot from seat against the board: along-baseline position finite and within
// [baseline_x_min, baseline_x_max]; striker not overlapping any piece on the board; angle finite;
// power finite and within [0, max_power]. Codes: "invalid_seat", "x_not_finite",
// "x_out_of_range", "striker_overlaps", "angle_not_finite", "power_not_finite",
// "power_out_of_range". Does not look at whose turn it is (see check_turn).
std::optional<RuleError> check_placement(const MatchState& state, int seat, const Shot& shot);

// The legal shot nearest to shot from seat, for a shot check_placement refuses: a position that
// is not finite goes to the middle of the baseline, one off it to its nearer end, one on a
// piece to the nearest free position of the baseline (searched in steps of 1/8 px outwards,
// the lower one first at equal distance); an angle that is not finite aims at the board centre;
// the power is clamped to [0, max_power] (0 when not finite). A legal shot comes back unchanged.
// nullopt for a seat that does not exist or a baseline with no free position. Deterministic.
std::optional<Shot> nearest_legal_shot(const MatchState& state, int seat, const Shot& shot);

// The free spot nearest the board centre for a disc of radius, among the unpocketed bodies:
// the centre itself when free, else the nearest point touching one or two bodies (closed form, so
// it is exactly the nearest one up to a clearance of 1e-6 px); within the cushions. Deterministic.
Vec2 free_spot_near_centre(const PhysicsConfig& physics, std::span<const Body> bodies,
                           double radius_px);

} // namespace carrom::rules
