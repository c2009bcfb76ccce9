#include "carrom/client/shot_timeline.hpp"

namespace carrom::client {

std::optional<double> ShotTimeline::start_of(int turn) const {
    const auto it = starts_.find(turn);
    return it != starts_.end() ? std::optional<double>(it->second) : std::nullopt;
}

void ShotTimeline::place(int turn, double start_s) {
    starts_[turn] = start_s;
    while (starts_.size() > kTurnsKept) {
        starts_.erase(starts_.begin());
    }
}

ShotTime ShotTimeline::shot_time(double continuous_s) const {
    ShotTime best;
    double best_start = 0.0;
    for (const auto& [turn, start] : starts_) {
        if (start <= continuous_s && (best.turn < 0 || start >= best_start)) {
            best = {turn, continuous_s - start};
            best_start = start;
        }
    }
    return best;
}

} // namespace carrom::client
