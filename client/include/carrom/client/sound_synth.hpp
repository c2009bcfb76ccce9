#pragma once
// Game sounds generated in code (no sample files): mono 16-bit PCM at a given rate. Pure and
// deterministic, so the app only hands the samples to its audio backend.

#include <cstdint>
#include <vector>

namespace carrom::client {

enum class SoundKind : std::uint8_t { Click, Cushion, Pocket };

inline constexpr unsigned kSampleRate = 44100;

// A wooden click (coin on coin, striker on coin), a dull thud (cushion), a drop and rattle
// (pocket). Peak amplitude is at most 0.9 of full scale.
std::vector<std::int16_t> synth_sound(SoundKind kind, unsigned sample_rate = kSampleRate);

// Loudness 0..1 from a collision impulse (mass * px/s), on a log scale: impulses at or below
// quiet_impulse are silent, loud_impulse and above are full volume.
double loudness_from_impulse(double impulse, double quiet_impulse = 5.0,
                             double loud_impulse = 2000.0);

// A sound to play when the rendered time reaches time_s (server match time).
struct SoundCue {
    double time_s = 0.0;
    SoundKind kind = SoundKind::Click;
    double volume = 1.0; // 0..1
};

// Cues wait until the board is rendered at their time, so sounds match what is seen.
class SoundCueQueue {
public:
    void push(const SoundCue& cue);
    // Cues with time_s <= render_time_s, in time order; cues that are more than stale_s late are
    // dropped instead (a resume or a stall should not play a burst of old clicks).
    std::vector<SoundCue> take_due(double render_time_s, double stale_s = 0.25);
    void clear() { cues_.clear(); }
    std::size_t size() const { return cues_.size(); }

private:
    std::vector<SoundCue> cues_; // sorted by time_s
};

} // namespace carrom::client
