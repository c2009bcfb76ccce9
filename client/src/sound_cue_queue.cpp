#include "carrom/client/sound_cue_queue.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

void SoundCueQueue::push(const SoundCue& cue) {
    if (!std::isfinite(cue.time_s)) {
        return;
    }
    const auto at = std::upper_bound(cues_.begin(), cues_.end(), cue.time_s,
                                     [](double t, const SoundCue& c) { return t < c.time_s; });
    cues_.insert(at, cue);
    if (cues_.size() > capacity_) {
        cues_.erase(cues_.begin());
    }
}

std::vector<SoundCue> SoundCueQueue::take_due(double render_time_s, double stale_s) {
    std::vector<SoundCue> due;
    auto it = cues_.begin();
    for (; it != cues_.end() && it->time_s <= render_time_s; ++it) {
        if (render_time_s - it->time_s <= stale_s) {
            due.push_back(*it);
        }
    }
    cues_.erase(cues_.begin(), it);
    return due;
}

} // namespace carrom::client
