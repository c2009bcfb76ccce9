#pragma once
// Glicko-2 (Mark Glickman, "Example of the Glicko-2 system", 2013): one rating period's update
// of one player's rating from the games of that period, and the deviation growth of periods
// without games. Deterministic: the same inputs give bit-identical outputs on one build.
//
// Rating periods (docs/ratings.md): the server rates every game on its own, as one period, at the
// game's end, against the opponent's rating before the game; each whole UTC day without a rated
// game in that rule set before it is one empty period (age()).

#include "carrom/ratings/rating.hpp"

#include <span>

namespace carrom::ratings {

struct GameScore {
    Rating opponent;    // the opponent's rating before the period
    double score = 0.0; // 1 win, 0.5 draw, 0 loss
};

struct Glicko2Params {
    double tau = 0.5;              // constrains the volatility's change; Glickman: 0.3..1.2
    double convergence = 0.000001; // epsilon of the volatility iteration (step 5)
    double max_deviation = kInitialDeviation; // no update leaves a deviation above this
};

class Glicko2 {
public:
    explicit Glicko2(Glicko2Params params = {}) : params_(params) {}

    // The rating after one period with these games; with no games, the deviation grows as in
    // age(player, 1).
    Rating rate(const Rating& player, std::span<const GameScore> games) const;

    // The rating after idle_periods periods without games: only the deviation grows,
    // phi' = sqrt(phi^2 + idle_periods * sigma^2), up to max_deviation. idle_periods <= 0 changes
    // nothing.
    Rating age(const Rating& player, long long idle_periods) const;

private:
    double new_volatility(double phi, double sigma, double delta, double v) const;

    Glicko2Params params_;
};

} // namespace carrom::ratings
