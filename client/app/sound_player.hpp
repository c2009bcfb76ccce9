#pragma once
// Plays the synthesised game sounds. Audio is optional: with --mute, or when the audio device
// cannot be opened (e.g. under Xvfb on a machine without sound), play() does nothing.

#include "carrom/client/sound_synth.hpp"

#include <SFML/Audio.hpp>

#include <array>
#include <memory>
#include <vector>

namespace carrom::client::app {

class SoundPlayer {
public:
    explicit SoundPlayer(bool enabled);
    void play(const SoundCue& cue);
    bool enabled() const { return enabled_; }

private:
    bool enabled_ = false;
    std::vector<sf::SoundBuffer> buffers_; // created only when audio is on (opens the device)
    std::vector<sf::Sound> voices_;        // created only when audio is on
    std::size_t next_ = 0;
};

} // namespace carrom::client::app
