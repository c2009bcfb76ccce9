#pragma once
// How good a match state between strokes is for a team, as one number in points of the bots'
// score (larger is better). Search strategies rank a simulated stroke by
//   stroke_score = position_value(after) - position_value(before) + turn_value(after)
// so a stroke is worth what it changed: coins off the board, the queen and its cover, dues,
// score points, boards and the game, plus who shoots next and what is left for them.
// Every rule set's scoring is here (icf, seed, freestyle, discpool). Plain and deterministic.

#include "carrom/rules/match_state.hpp"

namespace carrom::bots {

// Weights, in points of this score.
struct ValueWeights {
    double own_coin = 10.0;       // icf, discpool: an own coin off the board
    double opponent_coin = 8.0;   // icf, discpool: an opponent coin off the board (against)
    double due = 9.0;             // icf, discpool: a due the team owes (against)
    double queen_covered = 25.0;  // icf: the team covered the queen
    double queen_pending = 8.0;   // the team pocketed the queen and may cover it next stroke
    double game_point = 40.0;     // icf: a game point (boards won)
    double seed_point = 10.0;     // seed: a point (a coin of the team's colour, +3 for the queen)
    double freestyle_point = 0.5; // freestyle: a point (white 20, black 10, queen 50)
    double board_won = 300.0;     // a board won
    double game_won = 10000.0;    // the game won (lost: minus this)
    double keep_turn = 6.0;       // the shooter's team shoots next
    double easy_coin = 3.0;       // a wanted coin close to a pocket, for whoever shoots next
    double easy_range_px = 150.0; // beyond this from a pocket's edge a coin counts as not easy
};

// The value of state for team, from what is off the board, the queen, dues, scores, boards and
// the game result. Independent of whose turn it is.
double position_value(const rules::MatchState& state, int team, const ValueWeights& w = {});

// The value of whose turn it is in state for team: + keep_turn and the easy coins the team may
// pocket next when it shoots next; minus the opponents' easy coins when they do. 0 unless the
// phase is AwaitingShot.
double turn_value(const rules::MatchState& state, int team, const ValueWeights& w = {});

// True for a piece on the board that team may want to pocket: its own colour (any coin in
// freestyle), or the queen while it is on the board.
bool wants_to_pocket(const rules::MatchState& state, int team, const Body& body);

// Coins (and the queen while it is on the board) that team may want to pocket next, each
// weighted in [0, 1] by how close it is to its nearest pocket (1 at the pocket's edge, 0 at
// easy_range_px or more).
double easy_coins(const rules::MatchState& state, int team, const ValueWeights& w = {});

} // namespace carrom::bots
