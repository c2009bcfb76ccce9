#include "sound_player.hpp"

#include <cstdlib>

namespace carrom::client::app {

SoundPlayer::SoundPlayer(bool enabled) {
    if (!enabled) {
        return;
    }
    buffers_.resize(3);
    bool ok = true;
    for (SoundKind kind : {SoundKind::Click, SoundKind::Cushion, SoundKind::Pocket}) {
        const std::vector<std::int16_t> samples = synth_sound(kind);
        ok = ok && buffers_[static_cast<std::size_t>(kind)].loadFromSamples(
                       samples.data(), samples.size(), 1, kSampleRate);
    }
    enabled_ = ok;
    if (enabled_) {
        voices_.resize(12);
    }
}

void SoundPlayer::play(const SoundCue& cue) {
    if (!enabled_ || cue.volume <= 0.0) {
        return;
    }
    sf::Sound& voice = voices_[next_];
    next_ = (next_ + 1) % voices_.size();
    voice.stop();
    voice.setBuffer(buffers_[static_cast<std::size_t>(cue.kind)]);
    voice.setVolume(static_cast<float>(100.0 * std::clamp(cue.volume, 0.0, 1.0)));
    voice.play();
}

} // namespace carrom::client::app
