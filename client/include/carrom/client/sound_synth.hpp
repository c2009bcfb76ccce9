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
    friend bool operator==(const SoundCue&, const SoundCue&) = default;
};

} // namespace carrom::client
