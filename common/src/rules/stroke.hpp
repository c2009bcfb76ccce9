#pragma once
// Private to the rules engine: the state of one stroke being judged, and the small operations
// every rule set is written with. Each rule set's judge is a function of a Stroke.

#include "carrom/rules/match.hpp"

#include <optional>
#include <vector>

namespace carrom::rules::detail {

struct Stroke {
    MatchState state;          // the state being changed (a copy of the caller's)
    ShotOutcome outcome;       // being filled
    int seat = 0;              // the shooter
    int team = 0;              // the shooter's team
    std::vector<int> in;       // pieces pocketed this stroke, in order (never the striker)
    bool foul = false;         // striker pocketed
    bool touched = true;       // the striker touched a piece
    bool cover_stroke = false; // the queen was pending cover by this seat before the stroke
    std::vector<int> scores_before;
};

// Copies the state, applies the physics (positions, newly pocketed pieces appended to
// state.pocketed) and fills the outcome's header fields.
Stroke begin_stroke(const MatchState& state, int seat, const Shot& shot,
                    const StrokePhysics& physics);
// Places the pieces returned this stroke (the queen first, on the centre when it is free), sets
// scores deltas, queen_after, dues, next seat and turn number; returns the result.
StrokeResult finish_stroke(Stroke& s, bool extra_stroke);

int other_team(int team);
BodyKind other_colour(BodyKind colour);
Body& piece(MatchState& state, int id);
const Body& piece(const MatchState& state, int id);
bool contains(const std::vector<int>& ids, int id);
std::vector<int> of_kind(const Stroke& s, BodyKind kind);
// Pieces of kind off the board (in state.pocketed).
int count_pocketed(const MatchState& state, BodyKind kind);

// Puts a pocketed piece back on the board and records it; finish_stroke chooses its spot.
void return_piece(Stroke& s, int id, RuleCode reason);
// Returns the queen (if it is off the board) and sets it OnBoard.
void return_queen(Stroke& s, RuleCode reason);
void cover_queen(Stroke& s);
void add_foul(Stroke& s, RuleCode code);
// Takes the shooter team's owed dues from its most recently pocketed coins of colour.
void pay_dues(Stroke& s, BodyKind colour);

// Ends the board (and, depending on the rule set, the game). points go to the winner.
void end_board(Stroke& s, std::optional<int> winner_team, int points, RuleCode reason);
void end_game(MatchState& state, ShotOutcome& outcome, std::optional<int> winner_team,
              RuleCode reason);

// Each judge applies its rule set to a begun stroke and returns whether the shooter shoots again.
bool judge_icf(Stroke& s);
bool judge_seed(Stroke& s);
bool judge_freestyle(Stroke& s);
bool judge_discpool(Stroke& s);

} // namespace carrom::rules::detail
