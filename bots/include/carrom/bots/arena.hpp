#pragma once
// Offline games between strategies: the rules engine and the exact physics, no network and
// no clock but the strategies' own time budgets. Used by carrom-arena (docs/bots.md) to measure
// strategies against each other, and by tests. Singles (two seats) and doubles (four seats,
// partners opposite: seats 0 and 2 against 1 and 3).

#include "carrom/bots/strategy.hpp"
#include "carrom/rules/match.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace carrom::bots {

struct SeatRecord {
    int strokes = 0;             // strokes played
    int fouls = 0;               // strokes with at least one foul
    int pocketed = 0;            // pieces pocketed (any colour, the queen included)
    int refusals = 0;            // shots the rules refused (illegal placement or range)
    std::int64_t candidates = 0; // simulated by the strategy while choosing
    double think_s = 0.0;        // wall time spent choosing, s
};

struct GameRecord {
    std::optional<int> winner_team; // empty: a draw, or unfinished (singles: team == seat)
    bool finished = false;          // the game reached GameOver within max_strokes
    rules::RuleCode reason = rules::RuleCode::BoardCleared;
    int boards = 0;                // boards played (the last one included)
    std::vector<SeatRecord> seats; // one per seat of the match
    std::vector<int> scores;       // per team at the end
};

struct ArenaOptions {
    DecisionBudget budget{};
    int max_strokes = 3000; // a game not over by then is unfinished (a draw)
    int max_refusals = 20;  // refused shots in a row before the seat forfeits
};

// Plays one game from start (phase AwaitingShot) to its end: players[seat] chooses for seat,
// one player per seat of start (players.size() == start.seats.size(); otherwise nothing is
// played and the record is unfinished). Boards are started as they end.
GameRecord play_game(const rules::MatchState& start, const std::vector<Strategy*>& players,
                     const ArenaOptions& options);

} // namespace carrom::bots
