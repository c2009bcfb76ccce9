#include "carrom/client/sound_cue_schedule.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {
namespace {

// A cue's time in whole ms, rounded half up (as JavaScript's Math.round, for the web client).
double rounded_ms(double time_s) {
    return std::floor(time_s * 1000.0 + 0.5);
}

} // namespace

void SoundCueSchedule::add(int turn, double t_s, SoundKind kind, double volume,
                           std::optional<double> shot_start_s) {
    if (shot_start_s) {
        queue_.push({*shot_start_s + t_s, kind, volume});
        return;
    }
    waiting_.push_back({turn, t_s, kind, volume});
    if (waiting_.size() > kWaitingKept) {
        waiting_.pop_front();
    }
}

void SoundCueSchedule::start(int turn, double shot_start_s) {
    std::erase_if(waiting_, [&](const Waiting& w) {
        if (w.turn != turn) {
            return false;
        }
        queue_.push({shot_start_s + w.t_s, w.kind, w.volume});
        return true;
    });
}

void SoundCueSchedule::render_to(double render_time_s) {
    for (const SoundCue& c : queue_.take_due(render_time_s)) {
        due_.push_back(c);
    }
    const auto passed =
        std::find_if(predicted_.begin(), predicted_.end(),
                     [render_time_s](const SoundCue& c) { return c.time_s > render_time_s; });
    due_.insert(due_.end(), predicted_.begin(), passed);
    predicted_.erase(predicted_.begin(), passed);
}

std::vector<SoundCue> SoundCueSchedule::take() {
    std::vector<SoundCue> out;
    for (const SoundCue& cue : due_) {
        const auto same = std::find_if(out.begin(), out.end(), [&cue](const SoundCue& o) {
            return o.kind == cue.kind && rounded_ms(o.time_s) == rounded_ms(cue.time_s);
        });
        if (same == out.end()) {
            out.push_back(cue);
        } else if (cue.volume > same->volume) {
            *same = cue;
        }
    }
    due_.clear();
    return out;
}

void SoundCueSchedule::clear() {
    queue_.clear();
    waiting_.clear();
    predicted_.clear();
    due_.clear();
}

} // namespace carrom::client
