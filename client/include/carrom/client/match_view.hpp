#pragma once
// What the HUD shows of a match (seats, scores, turn, shot clock, queen, dues, the result), as
// MatchModel builds it from the server's messages, and the names and teams read from it.

#include "carrom/proto/server_messages.hpp"
#include "carrom/rules/seat.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client {

struct SeatView {
    bool occupied = false;
    std::string name;
    bool connected = false;
    bool bot = false;
    proto::Colour colour = proto::Colour::None;
    rules::Side side = rules::Side::Bottom; // the seat's baseline (room_state's "baseline")
    int score = 0;                          // the team's score (partners show the same)
    int dues = 0;                           // the team's dues
};

// How the game ended.
struct GameResult {
    int winner = -1; // the winning team (its first seat: singles the seat); -1: a draw
    // game_end's reason: "score", "boards", "cleared", "forfeit", "left" or "clock"; empty when
    // the client came in after the end (a room state that was already over).
    std::string reason;
    std::vector<int> scores;        // final, per seat (a seat's is its team's)
    std::vector<std::string> names; // per seat when the game ended (a seat may empty later)
    // game_end's rule: the rules engine's code of the end ("target_points", "boards_played",
    // ...); empty when the server sent none.
    std::string rule{};
};

// The name of the end that the journal, the Match API and carrom-bot's summary give it: the rule
// code, or game_end's reason from a server that sends no rule.
const std::string& game_end_name(const GameResult& result);

// A board that just ended, for the summary card shown before the next board
// (board_summary_text.hpp).
struct BoardSummary {
    int board = 1;
    int winner = -1;         // the board's winning team (its first seat), -1 none
    int points = 0;          // the points it won (0 in freestyle: every stroke scores)
    double shown_at_s = 0.0; // local time the board ended
    friend bool operator==(const BoardSummary&, const BoardSummary&) = default;
};

struct MatchView {
    bool in_room = false;
    std::string code;
    int you = -1; // our seat, -1 for a spectator
    proto::RuleSet rule_set = proto::RuleSet::Icf;
    proto::MatchOptions options;
    std::vector<SeatView> seats;
    int spectators = 0;
    int board_number = 1;
    int turn = 0;
    int to_play = 0;
    proto::Phase phase = proto::Phase::Waiting;
    proto::QueenInfo queen;
    int winner = -1;                         // team, -1 none
    std::optional<std::int64_t> deadline_ms; // shot clock, server clock
    std::optional<double> aim_x_px;          // the shooter's live striker x (aim events)
    std::optional<GameResult> result;        // from game over until a new game starts
    // The board that ended last, until its card is dismissed or the game ends with it.
    std::optional<BoardSummary> board_summary;
    bool aim_assist = true; // room_state's aim_assist: the first-contact guide is allowed
};

// The seat's name, or "Seat N" for a seat without one.
std::string seat_name(const MatchView& view, int seat);
// After a game: the name the seat had when it ended (its player may have left since).
std::string player_name_at_end(const MatchView& view, int seat);
// The team of a seat, -1 for no such seat: the rules' team for the room's seat count, which is
// room_state's "team" (singles: the seat; doubles: seat % 2, partners opposite).
int team_of(const MatchView& view, int seat);
// The seats of a team in seat order: one in singles, the two partners in doubles.
std::vector<int> team_seats(const MatchView& view, int team);
// The partner's seat in doubles, -1 in singles (or for no such seat).
int partner_of(const MatchView& view, int seat);
// A team's players as a sentence subject, e.g. "Asha & Ravi" (at the end of the game: the names
// they had then).
std::string team_name(const MatchView& view, int team);
// Who a team is in a HUD line: in doubles its players (team_name, "Asha & Ravi"), in singles the
// seat's name (the team's number is its first seat, as in the protocol's `winner`).
std::string team_subject(const MatchView& view, int team);
// The side a seat shoots from (its room_state baseline).
rules::Side seat_side(const MatchView& view, int seat);

} // namespace carrom::client
