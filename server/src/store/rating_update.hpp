#pragma once
// The rating update of one rated singles game (docs/ratings.md), shared by every backend: each
// player's stored rating is first aged by the whole days since their last rated game in the rule
// set, then both are rated against each other's aged rating, as one Glicko-2 period each.

#include "carrom/rules/match_state.hpp"
#include "store/player_records.hpp"

#include <array>
#include <cstdint>
#include <optional>

namespace carrom::store {

inline constexpr std::int64_t kRatingPeriodMs = 86'400'000; // one rating period: 24 hours

struct RatedSeat {
    PlayerKeyHash player{};
    std::optional<PlayerRating> stored; // none: the player's first rated game in the rule set
};

struct RatingOutcome {
    PlayerKeyHash player{};
    ratings::Rating before{}; // the aged rating the game was rated from
    PlayerRating after{};     // the row to store
    double score = 0.0;       // 1 win, 0.5 draw, 0 loss
};

// The two seats' (seat 0, seat 1) new ratings after a game that ended with result at time_ms.
std::array<RatingOutcome, 2> rate_singles_game(const std::array<RatedSeat, 2>& seats,
                                               rules::RuleSet rule_set,
                                               const rules::GameResult& result,
                                               std::int64_t time_ms);

} // namespace carrom::store
