#include "carrom/ratings/glicko2.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carrom::ratings {

namespace {

// Glicko scale <-> Glicko-2 scale (Glickman, steps 2 and 8).
constexpr double kGlicko2Scale = 173.7178;

double g_of(double phi) {
    return 1.0 / std::sqrt(1.0 + 3.0 * phi * phi / (std::numbers::pi * std::numbers::pi));
}

double expected_score(double mu, double mu_j, double phi_j) {
    return 1.0 / (1.0 + std::exp(-g_of(phi_j) * (mu - mu_j)));
}

} // namespace

Rating Glicko2::rate(const Rating& player, std::span<const GameScore> games) const {
    if (games.empty()) {
        return age(player, 1);
    }
    // Step 2: to the Glicko-2 scale.
    const double mu = (player.rating - kInitialRating) / kGlicko2Scale;
    const double phi = player.deviation / kGlicko2Scale;
    const double sigma = player.volatility;
    // Steps 3 and 4: the estimated variance v and the estimated improvement delta.
    double v_inverse = 0.0;
    double improvement_sum = 0.0;
    for (const GameScore& game : games) {
        const double mu_j = (game.opponent.rating - kInitialRating) / kGlicko2Scale;
        const double phi_j = game.opponent.deviation / kGlicko2Scale;
        const double g = g_of(phi_j);
        const double e = expected_score(mu, mu_j, phi_j);
        v_inverse += g * g * e * (1.0 - e);
        improvement_sum += g * (game.score - e);
    }
    const double v = 1.0 / v_inverse;
    const double delta = v * improvement_sum;
    // Step 5: the new volatility.
    const double sigma_new = new_volatility(phi, sigma, delta, v);
    // Steps 6 and 7: the new deviation and rating.
    const double phi_star = std::sqrt(phi * phi + sigma_new * sigma_new);
    const double phi_new = 1.0 / std::sqrt(1.0 / (phi_star * phi_star) + 1.0 / v);
    const double mu_new = mu + phi_new * phi_new * improvement_sum;
    // Step 8: back to the Glicko scale.
    return Rating{kInitialRating + kGlicko2Scale * mu_new,
                  std::min(kGlicko2Scale * phi_new, params_.max_deviation), sigma_new};
}

Rating Glicko2::age(const Rating& player, long long idle_periods) const {
    if (idle_periods <= 0) {
        return player;
    }
    const double phi = player.deviation / kGlicko2Scale;
    const double grown = std::sqrt(phi * phi + static_cast<double>(idle_periods) *
                                                   player.volatility * player.volatility);
    return Rating{player.rating, std::min(kGlicko2Scale * grown, params_.max_deviation),
                  player.volatility};
}

// Step 5 of Glickman's paper: the Illinois algorithm on f(x), x = ln(sigma'^2). At most 100
// iterations: the bracket halves at least every other step, far below epsilon by then.
double Glicko2::new_volatility(double phi, double sigma, double delta, double v) const {
    const double a = std::log(sigma * sigma);
    const double tau = params_.tau;
    const auto f = [&](double x) {
        const double ex = std::exp(x);
        const double denominator = phi * phi + v + ex;
        return ex * (delta * delta - phi * phi - v - ex) / (2.0 * denominator * denominator) -
               (x - a) / (tau * tau);
    };
    double upper_a = a;
    double upper_b = 0.0;
    if (delta * delta > phi * phi + v) {
        upper_b = std::log(delta * delta - phi * phi - v);
    } else {
        int k = 1;
        while (f(a - k * tau) < 0.0 && k < 1000) {
            ++k;
        }
        upper_b = a - k * tau;
    }
    double f_a = f(upper_a);
    double f_b = f(upper_b);
    for (int iteration = 0; iteration < 100 && std::abs(upper_b - upper_a) > params_.convergence;
         ++iteration) {
        const double c = upper_a + (upper_a - upper_b) * f_a / (f_b - f_a);
        const double f_c = f(c);
        if (f_c * f_b <= 0.0) {
            upper_a = upper_b;
            f_a = f_b;
        } else {
            f_a /= 2.0;
        }
        upper_b = c;
        f_b = f_c;
    }
    return std::exp(upper_a / 2.0);
}

} // namespace carrom::ratings
