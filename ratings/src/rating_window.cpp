#include "carrom/ratings/rating_window.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::ratings {

double acceptable_gap(double waited_s) {
    return kInitialGap + kGapPerSecond * std::floor(std::max(waited_s, 0.0));
}

std::optional<std::pair<std::size_t, std::size_t>>
closest_acceptable_pair(std::span<const WaitingPlayer> waiting) {
    std::optional<std::pair<std::size_t, std::size_t>> best;
    double best_gap = 0.0;
    for (std::size_t i = 0; i < waiting.size(); ++i) {
        for (std::size_t j = i + 1; j < waiting.size(); ++j) {
            const double gap = std::abs(waiting[i].rating - waiting[j].rating);
            const double allowed =
                acceptable_gap(std::max(waiting[i].waited_s, waiting[j].waited_s));
            if (gap <= allowed && (!best || gap < best_gap)) {
                best = std::pair{i, j};
                best_gap = gap;
            }
        }
    }
    return best;
}

} // namespace carrom::ratings
