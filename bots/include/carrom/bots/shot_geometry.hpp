#pragma once
// Helpers every strategy needs: the baseline range, legal placement, the forward direction.
// A shot's x_px is the striker's position along the seat's own baseline (x for the bottom and top
// seats, y for the right and left ones; rules::striker_for), the same range on every side.

#include "carrom/rules/match_state.hpp"
#include "carrom/scene.hpp"

#include <optional>

namespace carrom::bots {

struct BaselineRange {
    double min_px = 0.0; // striker centre along the baseline, px
    double max_px = 0.0;
};
BaselineRange baseline_range(const rules::MatchState& state);

// True when the rules accept the shot's placement and ranges from seat.
bool shot_is_legal(const rules::MatchState& state, int seat, const Shot& shot);

// The legal striker position nearest x_px on the seat's baseline (searching outwards in 0.5 px
// steps), or nothing when the whole baseline is blocked.
std::optional<double> nearest_legal_x(const rules::MatchState& state, int seat, double x_px);

// The angle (radians, screen convention: 0 = +x, pi/2 = +y down) pointing from the seat's
// baseline straight into the board: -pi/2 for the bottom seat, pi for the right one, +pi/2 for
// the top one, 0 for the left one (doubles seats 1 and 3).
double forward_angle(const rules::MatchState& state, int seat);

} // namespace carrom::bots
