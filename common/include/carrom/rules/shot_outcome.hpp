#pragma once
// What one stroke (or clock expiry, or forfeit) did, as data.

#include "carrom/body.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/rules/rule_code.hpp"
#include "carrom/scene.hpp"

#include <optional>
#include <vector>

namespace carrom::rules {

struct Foul {
    RuleCode code = RuleCode::StrikerPocketed;
    int seat = 0; // who committed it
};

// A piece put back on the board at pos_px (the free spot nearest the centre).
struct ReturnedPiece {
    int id = 0;
    BodyKind kind = BodyKind::Black;
    Vec2 pos_px{};
    RuleCode reason = RuleCode::StrikerPocketed; // StrikerPocketed, DuePaid, QueenNotCovered,
                                                 // QueenBeforeOwnCoin
};

struct ShotOutcome {
    int seat = 0;                  // the shooter (or the seat whose clock ran out / forfeited)
    int turn_number = 0;           // the state's turn_number when the stroke was taken
    bool shot_taken = false;       // false for clock expiry and forfeit
    Shot shot{};                   // as played (when shot_taken)
    std::vector<int> pocketed;     // piece ids pocketed by this stroke, in order; not the striker
    bool striker_pocketed = false; //
    std::vector<Foul> fouls;
    std::vector<ReturnedPiece> returned; // in the order they were placed
    int dues_incurred = 0;               // by the shooter's team on this stroke
    int dues_paid = 0;                   // by the shooter's team on this stroke
    int dues_owed = 0;                   // the shooter's team still owes after the stroke
    QueenState queen_before{};
    QueenState queen_after{};
    std::vector<int> score_changes; // per team
    bool extra_stroke = false;      // the shooter shoots again
    int next_seat = 0;              // whose stroke is next (meaningless once the game is over)
    std::optional<BoardResult> board_end;
    std::optional<GameResult> game_end;
    SimResult physics; // the simulation of the stroke (empty when !shot_taken)
};

} // namespace carrom::rules
