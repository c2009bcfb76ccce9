#pragma once
// When the match's sounds play: the server's physics events as cues on the shot timeline (or
// waiting for their shot's start), the predicted stroke's cues, and the cues the drawn time has
// passed, handed out once each with simultaneous cues of one kind merged. Times are continuous
// (shot_timeline.hpp), seconds.

#include "carrom/client/sound_cue_queue.hpp"
#include "carrom/client/sound_synth.hpp"

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace carrom::client {

class SoundCueSchedule {
public:
    // Cues of turns whose start is not known yet kept at most (the oldest are dropped).
    static constexpr std::size_t kWaitingKept = 256;

    // A cue at shot time t_s of turn: at shot_start_s + t_s when the shot's start is known, else
    // it waits for start(turn, ...).
    void add(int turn, double t_s, SoundKind kind, double volume,
             std::optional<double> shot_start_s);
    // Turn's t = 0 is now known: its waiting cues are placed.
    void start(int turn, double shot_start_s);
    // The predicted stroke's cues (sorted by time), played as the drawn time passes them.
    void set_predicted(std::vector<SoundCue> cues) { predicted_ = std::move(cues); }
    void drop_predicted() { predicted_.clear(); }
    // The board is drawn at render_time_s: the cues it passed become due (server cues more than
    // 0.25 s late are dropped, SoundCueQueue).
    void render_to(double render_time_s);
    // The cues due since the last call, each once, in the order they became due; cues of one kind
    // at the same time (rounded to the ms: a straight break hits two mirrored coins at once)
    // are one cue, the loudest (the first of equally loud ones).
    std::vector<SoundCue> take();
    void clear();

private:
    struct Waiting {
        int turn;
        double t_s;
        SoundKind kind;
        double volume;
    };
    SoundCueQueue queue_;
    std::deque<Waiting> waiting_;
    std::vector<SoundCue> predicted_; // sorted by time
    std::vector<SoundCue> due_;
};

} // namespace carrom::client
