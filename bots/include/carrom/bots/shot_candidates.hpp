#pragma once
// Candidate strokes for search strategies: legal striker positions along the baseline, a plain
// grid of angles and powers, and aimed shots (the striker sent to the "ghost" position from
// which it knocks a wanted coin straight at a pocket). Geometry only: nothing is simulated here.

#include "carrom/bots/stroke_evaluator.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/scene.hpp"

#include <span>
#include <vector>

namespace carrom::bots {

// count striker positions evenly spaced over the baseline range (ends included), each moved to
// the nearest legal position when blocked; duplicates removed; ascending. Empty when the whole
// baseline is blocked.
std::vector<double> legal_baseline_xs(const StrokeEvaluator& evaluator, int count);

struct GridSpec {
    int angle_steps = 55;     // angles evenly spaced over [-spread, +spread] around forward
    double spread_rad = 1.40; // about 80 degrees either side of straight ahead
    std::vector<double> power_fractions{0.3, 0.6, 1.0}; // of max_power
};

// Every (x, angle, power) of the grid, x from xs.
std::vector<Shot> grid_shots(const rules::MatchState& state, int seat, std::span<const double> xs,
                             const GridSpec& spec);

struct AimSpec {
    double max_cut_rad = 1.36;         // about 78 degrees: thinner cuts are not tried
    double max_off_forward_rad = 1.50; // directions within about 86 degrees of straight ahead
    // Powers tried per aim, as multiples of the power that just gets the coin to the pocket.
    std::vector<double> power_factors{1.15, 1.7, 2.6};
};

// Ghost-ball shots from every x at every coin team may want (own colour, any coin in freestyle,
// the queen while on the board) into every pocket, where the ghost position lies inside the
// cushions, the cut is no thinner than max_cut_rad and the direction points into the board.
std::vector<Shot> aimed_shots(const rules::MatchState& state, int seat, std::span<const double> xs,
                              const AimSpec& spec);

} // namespace carrom::bots
