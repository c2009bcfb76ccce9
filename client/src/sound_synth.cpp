#include "carrom/client/sound_synth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carrom::client {
namespace {

// Small deterministic noise source in [-1, 1].
class Noise {
public:
    double next() {
        state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state_ >> 11) / static_cast<double>(1ULL << 52) - 1.0;
    }

private:
    std::uint64_t state_ = 0x9E3779B97F4A7C15ULL;
};

struct Voice {
    double duration_s;
    double tone_hz_start;
    double tone_hz_end;
    double tone_decay_s; // exponential time constant of the tone
    double noise_amount;
    double noise_decay_s;
};

Voice voice_for(SoundKind kind) {
    switch (kind) {
    case SoundKind::Click:
        return {0.045, 2600.0, 2200.0, 0.008, 0.6, 0.003};
    case SoundKind::Cushion:
        return {0.12, 170.0, 120.0, 0.035, 0.35, 0.010};
    case SoundKind::Pocket:
        return {0.30, 320.0, 90.0, 0.090, 0.25, 0.060};
    }
    return {0.05, 1000.0, 1000.0, 0.01, 0.0, 0.01};
}

} // namespace

std::vector<std::int16_t> synth_sound(SoundKind kind, unsigned sample_rate) {
    const Voice v = voice_for(kind);
    const double rate = static_cast<double>(std::max(sample_rate, 8000u));
    const auto count = static_cast<std::size_t>(v.duration_s * rate);
    std::vector<double> wave(count);
    Noise noise;
    double phase = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
        const double t = static_cast<double>(i) / rate;
        const double f = v.tone_hz_start + (v.tone_hz_end - v.tone_hz_start) * t / v.duration_s;
        phase += 2.0 * std::numbers::pi * f / rate;
        const double tone = std::sin(phase) * std::exp(-t / v.tone_decay_s);
        const double hiss = v.noise_amount * noise.next() * std::exp(-t / v.noise_decay_s);
        const double attack = std::min(1.0, t / 0.0008); // no click from a hard start
        const double release = std::min(1.0, (v.duration_s - t) / 0.005);
        wave[i] = (tone + hiss) * attack * release;
    }
    double peak = 0.0;
    for (double s : wave) {
        peak = std::max(peak, std::abs(s));
    }
    const double gain = peak > 0.0 ? 0.9 * 32767.0 / peak : 0.0;
    std::vector<std::int16_t> out(count);
    for (std::size_t i = 0; i < count; ++i) {
        out[i] = static_cast<std::int16_t>(std::lround(wave[i] * gain));
    }
    return out;
}

double loudness_from_impulse(double impulse, double quiet_impulse, double loud_impulse) {
    if (!(impulse > quiet_impulse)) {
        return 0.0;
    }
    const double level = std::log(impulse / quiet_impulse) / std::log(loud_impulse / quiet_impulse);
    return std::clamp(level, 0.0, 1.0);
}

} // namespace carrom::client
