#pragma once
// What the card between two boards says, in plain words, from the reader's side: who won the
// board, its points and the score, and the colour the player has on the next board (colours
// change hands with the board in icf and seed).

#include "carrom/client/match_view.hpp"

#include <string>

namespace carrom::client {

struct BoardSummaryText {
    std::string title;   // "You won board 1", "Bot (easy) won board 2", "Board 3: no winner"
    std::string points;  // "+3 points. Score: you 3, Bot (easy) 0" (our team first)
    std::string colours; // "Board 2: you play black" (empty without colours or for a spectator)
    friend bool operator==(const BoardSummaryText&, const BoardSummaryText&) = default;
};

// For a view with a board_summary (after the next board's room_state, for its colours).
BoardSummaryText board_summary_text(const MatchView& view);

} // namespace carrom::client
