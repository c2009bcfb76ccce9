#include "carrom/client/sound_synth.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace carrom::client {
namespace {

int peak(const std::vector<std::int16_t>& s) {
    int p = 0;
    for (std::int16_t v : s) {
        p = std::max(p, std::abs(static_cast<int>(v)));
    }
    return p;
}

TEST(SoundSynth, EachSoundHasItsLengthAndAHealthyLevel) {
    const auto click = synth_sound(SoundKind::Click);
    const auto cushion = synth_sound(SoundKind::Cushion);
    const auto pocket = synth_sound(SoundKind::Pocket);
    EXPECT_EQ(click.size(), static_cast<std::size_t>(0.045 * kSampleRate));
    EXPECT_LT(click.size(), cushion.size());
    EXPECT_LT(cushion.size(), pocket.size());
    for (const auto* s : {&click, &cushion, &pocket}) {
        EXPECT_LE(peak(*s), static_cast<int>(0.9 * 32767.0) + 1);
        EXPECT_GE(peak(*s), static_cast<int>(0.9 * 32767.0) - 1);
        // Starts and ends near silence: no clicks from the edges.
        EXPECT_LT(std::abs(static_cast<int>(s->front())), 2000);
        EXPECT_LT(std::abs(static_cast<int>(s->back())), 2000);
    }
}

TEST(SoundSynth, IsDeterministic) {
    EXPECT_EQ(synth_sound(SoundKind::Pocket), synth_sound(SoundKind::Pocket));
    EXPECT_EQ(synth_sound(SoundKind::Click, 22050).size(), static_cast<std::size_t>(0.045 * 22050));
}

TEST(Loudness, LogScaleBetweenQuietAndLoud) {
    EXPECT_DOUBLE_EQ(loudness_from_impulse(0.0), 0.0);
    EXPECT_DOUBLE_EQ(loudness_from_impulse(5.0), 0.0);
    EXPECT_DOUBLE_EQ(loudness_from_impulse(2000.0), 1.0);
    EXPECT_DOUBLE_EQ(loudness_from_impulse(1e9), 1.0);
    EXPECT_NEAR(loudness_from_impulse(100.0, 10.0, 1000.0), 0.5, 1e-12);
    EXPECT_LT(loudness_from_impulse(50.0), loudness_from_impulse(500.0));
    EXPECT_DOUBLE_EQ(loudness_from_impulse(std::nan("")), 0.0);
    EXPECT_DOUBLE_EQ(loudness_from_impulse(-3.0), 0.0);
}

} // namespace
} // namespace carrom::client
