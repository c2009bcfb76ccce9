#include "carrom/ratings/rating.hpp"

#include <cmath>

namespace carrom::ratings {

bool is_provisional(const Rating& rating) {
    return rating.deviation >= kProvisionalDeviation;
}

std::string rating_label(const Rating& rating) {
    std::string label = std::to_string(std::lround(rating.rating));
    if (is_provisional(rating)) {
        label += '?';
    }
    return label;
}

std::string rating_change_label(const Rating& before, const Rating& after) {
    const long change = std::lround(after.rating) - std::lround(before.rating);
    return (change >= 0 ? "+" : "") + std::to_string(change);
}

} // namespace carrom::ratings
