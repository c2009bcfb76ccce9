#pragma once
// The whole state of a match between strokes, as plain data. Everything the rules need is here
// (including both configs), so every rules function is a pure function of its arguments.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/rules/rule_code.hpp"
#include "carrom/rules/rule_set.hpp"
#include "carrom/rules/rules_config.hpp"
#include "carrom/rules/seat.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace carrom::rules {

enum class Phase : std::uint8_t {
    AwaitingShot, // turn_seat is to shoot
    BoardOver,    // the board ended; start_next_board() sets up the next one
    GameOver,     // result is set
};

enum class QueenStatus : std::uint8_t {
    OnBoard,      // on the board
    PendingCover, // pocketed by seat; must be covered in the same or the very next stroke
    Covered,      // pocketed and covered by seat; stays off the board for the rest of the board
    OutOfPlay,    // discpool: no queen
};

struct QueenState {
    QueenStatus status = QueenStatus::OnBoard;
    int seat = -1; // who pocketed (PendingCover) or covered (Covered) it; -1 otherwise
};

// A piece that is off the board on the current board, in the order pieces went in. A piece that
// comes back (foul, due, uncovered queen) leaves this list.
struct PocketedPiece {
    int id = 0;
    BodyKind kind = BodyKind::Black;
    int seat = 0;        // the shooter of the stroke that pocketed it
    int turn_number = 0; // MatchState::turn_number of that stroke
};

struct BoardResult {
    int board = 1;
    std::optional<int> winner_team; // empty: no winner (freestyle/seed draw)
    int points = 0;                 // icf: points the winner scored for the board
    RuleCode reason = RuleCode::BoardCleared;
    friend bool operator==(const BoardResult&, const BoardResult&) = default;
};

struct GameResult {
    std::optional<int> winner_team; // empty: a draw
    RuleCode reason = RuleCode::BoardCleared;
    friend bool operator==(const GameResult&, const GameResult&) = default;
};

struct MatchState {
    RuleSet rule_set = RuleSet::Icf;
    RulesConfig config{};
    PhysicsConfig physics{};
    std::vector<Seat> seats;
    // The 19 pieces, ids 0..18 as scene.hpp lays them out (queen 0); never the striker.
    // Pocketed pieces keep pocketed = true (their position is meaningless).
    std::vector<Body> bodies;
    std::vector<PocketedPiece> pocketed; // this board's pieces off the board, oldest first
    std::vector<int> scores;             // per team; icf: game points; others: running points
    std::vector<int> dues_owed;          // per team: coins owed to the centre (icf, discpool)
    std::vector<int> missed_turns;       // per seat: clock expiries in a row
    int board = 1;                       // 1-based board number
    int breaker = 0;                     // seat that broke this board (its team plays white in icf)
    int turn_seat = 0;                   // whose stroke it is
    int turn_number = 0;                 // +1 on every stroke, clock expiry, forfeit, new board
    int strokes_this_board = 0;          // strokes taken on this board (a missed break counts)
    int break_tries = 0;                 // icf: missed break tries so far on this board
    bool break_done = false;             // icf: a stroke touched a coin on this board
    QueenState queen{};
    Phase phase = Phase::AwaitingShot;
    std::vector<BoardResult> boards;  // results of finished boards, in order
    std::optional<GameResult> result; // set when phase == GameOver
};

// The colour team plays on the current board: icf and discpool: the breaker's team plays white;
// seed: team 0 black, team 1 white; freestyle: none (any coin scores).
std::optional<BodyKind> team_colour(const MatchState& state, int team);
int team_of(const MatchState& state, int seat);
int count_on_board(const MatchState& state, BodyKind kind);

} // namespace carrom::rules
