#pragma once
// How good a stroke's outcome is for the shooter, as one number (larger is better). Used by
// search strategies to rank simulated candidates; plain and deterministic.

#include "carrom/rules/match.hpp"

namespace carrom::bots {

// Weights, in points of this score.
struct ScoreWeights {
    double own_coin = 10.0;      // own colour (any coin in freestyle) pocketed
    double opponent_coin = -6.0; // the opponent's colour pocketed
    double queen_pending = 6.0;  // queen pocketed, awaiting cover
    double queen_covered = 20.0; // queen covered
    double foul = -30.0;         // each foul
    double extra_stroke = 3.0;   // the shooter plays again
    double score_point = 5.0;    // per point of score change (own minus opponent's)
    double board_won = 200.0;
    double game_won = 1000.0; // (lost: minus this)
};

// Score of `after` (the rules' result of a stroke by seat from `before`).
double score_outcome(const rules::MatchState& before, const rules::PlayResult& after, int seat,
                     const ScoreWeights& weights = {});

} // namespace carrom::bots
