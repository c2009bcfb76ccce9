#pragma once
// What each side still has to pocket, counted from the board as it is drawn: a piece falling
// into a pocket is already gone, a piece the rules put back is there again once it is drawn.

#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/proto/types.hpp"

#include <optional>
#include <vector>

namespace carrom::client {

struct CoinsOnBoard {
    int white = 0;
    int black = 0;
    bool queen = false;
    friend bool operator==(const CoinsOnBoard&, const CoinsOnBoard&) = default;
};

// Counts the drawn coins that are not falling into a pocket (the striker is no coin).
CoinsOnBoard count_coins(const std::vector<RenderedBody>& drawn);

// The coins one seat plays for, and how many of them are still on the board.
struct SeatCoins {
    proto::Colour colour = proto::Colour::None; // None: any coin (freestyle)
    int coins = 0;                              // of that colour (or of both) on the board
    bool queen = false;                         // the queen is on the board, still to be won
    friend bool operator==(const SeatCoins&, const SeatCoins&) = default;
};

// icf, seed and discpool: the seat's own colour (nothing while the seat has none); freestyle:
// every coin, for both seats. The queen counts where the rule set has one (not in discpool).
std::optional<SeatCoins> seat_coins(const CoinsOnBoard& board, proto::RuleSet rule_set,
                                    proto::Colour seat_colour);

} // namespace carrom::client
