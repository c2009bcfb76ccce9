#pragma once
// Plays the synthesised game sounds. Audio is optional: with --mute (or for screenshots and the
// benchmark) no device is opened; when the audio device cannot be opened (e.g. under Xvfb on a
// machine without a sound card) the player says so once on stderr and play() does nothing.

#include "carrom/client/sound_synth.hpp"

#include <SFML/Audio.hpp>

#include <array>
#include <memory>
#include <vector>

namespace carrom::client::app {

class SoundPlayer {
public:
    explicit SoundPlayer(bool enabled);
    // At the settings' volume (0..1, times the cue's own); nothing while muted.
    void play(const SoundCue& cue, double volume = 1.0, bool muted = false);
    bool enabled() const { return enabled_; }

private:
    bool enabled_ = false;
    std::vector<sf::SoundBuffer> buffers_; // created only when audio is on (opens the device)
    std::vector<sf::Sound> voices_;        // created only when the device opened
    std::size_t next_ = 0;
};

} // namespace carrom::client::app
