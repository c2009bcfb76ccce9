#pragma once
// Offline games between two strategies: the rules engine and the exact physics, no network and
// no clock but the strategies' own time budgets. Used by carrom-arena (docs/bots.md) to measure
// strategies against each other, and by tests.

#include "carrom/bots/strategy.hpp"
#include "carrom/rules/match.hpp"

#include <array>
#include <cstdint>
#include <optional>

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
    std::optional<int> winner_seat; // empty: a draw, or unfinished
    bool finished = false;          // the game reached GameOver within max_strokes
    rules::RuleCode reason = rules::RuleCode::BoardCleared;
    int boards = 0; // boards played (the last one included)
    std::array<SeatRecord, 2> seats{};
    std::vector<int> scores; // per team at the end
};

struct ArenaOptions {
    DecisionBudget budget{};
    int max_strokes = 3000; // a game not over by then is unfinished (a draw)
    int max_refusals = 20;  // refused shots in a row before the seat forfeits
};

// Plays one game from start (phase AwaitingShot; two seats) to its end: players[seat] chooses
// for seat. Boards are started as they end.
GameRecord play_game(const rules::MatchState& start, std::array<Strategy*, 2> players,
                     const ArenaOptions& options);

} // namespace carrom::bots
