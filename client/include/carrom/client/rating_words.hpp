#pragma once
// The words both clients use for ratings (docs/ratings.md; the web page's rating_view.js says the
// same): the lobby's line "Rating: ICF 1532 (+14)", a seat's "1520?", the change after a rated
// game "1532 (+14)". No I/O.

#include "carrom/client/player_record.hpp"

#include <optional>
#include <string>
#include <vector>

namespace carrom::client {

// "ICF", "classic", "freestyle", "disc pool" for the API's rule set names; others as they are.
std::string rating_rule_set_word(const std::string& rule_set);

// The change from before to after, rounded ratings subtracted: "(+14)", "(-3)", "(+0)".
std::string rating_change_text(double before, double after);

// The lobby's line for `after` (a player's ratings), with the change from `before` (the ratings
// as the last game began; none: no earlier read) where the games played grew; a rule set new
// since `before` shows its change from 1500. "" when there are no ratings.
std::string rating_line(const std::optional<std::vector<RatingEntry>>& before,
                        const std::vector<RatingEntry>& after);

// A seat's rating for rule_set beside its name: "1532", "1520?"; with `before` (the rating as
// the game began) and more games played: "1532 (+14)". "" when the player has no such rating.
std::string seat_rating_text(const std::string& rule_set, const std::vector<RatingEntry>& after,
                             const std::optional<std::vector<RatingEntry>>& before);

} // namespace carrom::client
