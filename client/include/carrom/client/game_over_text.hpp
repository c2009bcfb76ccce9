#pragma once
// What the game-over panel says, in plain words: who won, why the game ended, the final score,
// and what the player can do next (a rematch, or back to the lobby).

#include "carrom/client/match_model.hpp"

#include <string>

namespace carrom::client {

struct GameOverText {
    std::string title;        // "You won!", "You lost", "Ana won", "A draw"
    std::string reason;       // one sentence: why the game ended
    std::string score;        // "Final score: Ana 25, Ben 13" (our seat first)
    bool can_rematch = false; // a seated player who has not asked for one yet, at a full table
    // Another seat is empty (its player left): no Rematch button, `waiting` says why.
    bool opponent_left = false;
    // After asking for a rematch: who it waits for ("Waiting for Ben to agree to a rematch"); at a
    // table a player left: "Your opponent left the room: no rematch".
    std::string waiting;
    // After a rated game: "Ratings: Asha 1662? (+162), Ravi 1338? (-162)" (set by the client
    // from the ratings it read, rating_book.hpp; "" otherwise).
    std::string ratings;
    friend bool operator==(const GameOverText&, const GameOverText&) = default;
};

// For a view with a result (MatchView::result); `rematch_asked`: this client sent `rematch`
// for this game.
GameOverText game_over_text(const MatchView& view, bool rematch_asked);

} // namespace carrom::client
