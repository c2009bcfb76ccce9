#pragma once
// One player's rating in one rule set, on the Glicko scale (docs/ratings.md): rating in points
// (a new player starts at 1500), deviation in points (the rating's uncertainty, one standard
// deviation; 350 for a new player, never more), volatility (the expected fluctuation of the
// player's strength, on the Glicko-2 scale; 0.06 for a new player).

#include <string>

namespace carrom::ratings {

inline constexpr double kInitialRating = 1500.0;
inline constexpr double kInitialDeviation = 350.0; // also the largest deviation
inline constexpr double kInitialVolatility = 0.06;
// A rating whose deviation is at least this is provisional: shown with a '?' ("1520?") and left
// off the leaderboard. 110 points is the deviation after 10 games from a new rating against
// established players (docs/ratings.md, "Provisional ratings").
inline constexpr double kProvisionalDeviation = 110.0;

struct Rating {
    double rating = kInitialRating;
    double deviation = kInitialDeviation;
    double volatility = kInitialVolatility;
    friend bool operator==(const Rating&, const Rating&) = default;
};

// deviation >= kProvisionalDeviation.
bool is_provisional(const Rating& rating);

// The rating rounded to whole points, with '?' after it when provisional: "1520?", "1687".
std::string rating_label(const Rating& rating);

// The rounded change between two ratings with its sign: "+14", "-9", "+0".
std::string rating_change_label(const Rating& before, const Rating& after);

} // namespace carrom::ratings
