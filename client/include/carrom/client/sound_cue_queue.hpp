#pragma once
// Sound cues waiting until the board is rendered at their time, so sounds match what is seen.

#include "carrom/client/sound_synth.hpp"

#include <cstddef>
#include <vector>

namespace carrom::client {

class SoundCueQueue {
public:
    // At most `capacity` cues wait (a window that draws no frames takes none); pushing one more
    // drops the earliest.
    explicit SoundCueQueue(std::size_t capacity = 512) : capacity_(capacity) {}
    // Cues with a time that is not finite are ignored; equal times keep their push order.
    void push(const SoundCue& cue);
    // Cues with time_s <= render_time_s, in time order; cues that are more than stale_s late are
    // dropped instead (a resume or a stall should not play a burst of old clicks).
    std::vector<SoundCue> take_due(double render_time_s, double stale_s = 0.25);
    void clear() { cues_.clear(); }
    std::size_t size() const { return cues_.size(); }

private:
    std::size_t capacity_;
    std::vector<SoundCue> cues_; // sorted by time_s
};

} // namespace carrom::client
