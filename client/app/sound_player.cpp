#include "sound_player.hpp"

#include <SFML/System/Err.hpp>

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace carrom::client::app {
namespace {

// While alive, file descriptor 2 goes to /dev/null. Opening a missing audio device makes ALSA
// and OpenAL Soft print a dozen lines there themselves (not through SFML's error stream). Used
// only in the SoundPlayer's constructor, before the window and the network thread exist, so no
// other message is lost.
class StderrMuted {
public:
    StderrMuted() {
        std::fflush(stderr);
        std::cerr.flush();
        saved_ = ::dup(2);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved_ >= 0 && null >= 0) {
            ::dup2(null, 2);
        }
        if (null >= 0) {
            ::close(null);
        }
    }
    ~StderrMuted() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            ::dup2(saved_, 2);
            ::close(saved_);
        }
    }
    StderrMuted(const StderrMuted&) = delete;
    StderrMuted& operator=(const StderrMuted&) = delete;

private:
    int saved_ = -1;
};

// Loads the three sounds into `buffers`; the first buffer opens SFML's audio device. If SFML
// reports any error meanwhile (when the device does not open: "Failed to open the audio device",
// then AL_INVALID_OPERATION for every OpenAL call) the buffers are dropped again and the answer
// is false. Nothing of this reaches stderr.
bool load_sounds(std::vector<sf::SoundBuffer>& buffers) {
    std::ostringstream reported;
    std::streambuf* const sfml_err = sf::err().rdbuf(reported.rdbuf());
    bool ok = true;
    {
        const StderrMuted muted;
        buffers.resize(3);
        for (SoundKind kind : {SoundKind::Click, SoundKind::Cushion, SoundKind::Pocket}) {
            const std::vector<std::int16_t> samples = synth_sound(kind);
            ok = ok && buffers[static_cast<std::size_t>(kind)].loadFromSamples(
                           samples.data(), samples.size(), 1, kSampleRate);
        }
        ok = ok && reported.str().empty();
        if (!ok) {
            buffers.clear(); // closes the device SFML tried to open
        }
    }
    sf::err().rdbuf(sfml_err);
    return ok;
}

} // namespace

SoundPlayer::SoundPlayer(bool enabled) {
    if (!enabled) {
        return;
    }
    enabled_ = load_sounds(buffers_);
    if (!enabled_) {
        std::cerr << "carrom-client: no audio device: sounds are off" << std::endl;
        return;
    }
    voices_.resize(12);
}

void SoundPlayer::play(const SoundCue& cue, double volume, bool muted) {
    if (!enabled_ || muted || cue.volume * volume <= 0.0) {
        return;
    }
    sf::Sound& voice = voices_[next_];
    next_ = (next_ + 1) % voices_.size();
    voice.stop();
    voice.setBuffer(buffers_[static_cast<std::size_t>(cue.kind)]);
    voice.setVolume(static_cast<float>(100.0 * std::clamp(cue.volume * volume, 0.0, 1.0)));
    voice.play();
}

} // namespace carrom::client::app
