#pragma once
// Maps the local clock to the server match time the board is rendered at: a short, adaptive
// delay behind the newest snapshot, so that there is (almost) always a snapshot on each side of
// the rendered instant even when snapshots arrive unevenly.
//
//   render time = local time - base transit - delay
//   base transit = smallest (arrival - server time) seen over the recent window (the clock offset
//                  plus the fastest network path)
//   delay = interval_factor * snapshot interval + measured jitter (a decaying peak of how much
//           later than the fastest path snapshots arrive), clamped to [min_delay_s, max_delay_s]
//
// The rendered time advances with the local clock and is pulled towards its target by at most
// slew_rate of the elapsed time, so that delay changes never make motion jump or run backwards.
// Units: s.

#include <cstddef>
#include <deque>

namespace carrom::client {

struct PlayoutConfig {
    double interval_factor = 2.0; // delay in snapshot intervals, before jitter
    double initial_interval_s = 1.0 / 60.0;
    double min_delay_s = 0.010;
    double max_delay_s = 0.300;
    double jitter_decay_s = 3.0;      // time constant of the jitter peak's decay
    double gap_s = 0.25;              // snapshots further apart than this are separate runs
    std::size_t transit_window = 180; // snapshots kept for the base transit minimum
    double slew_rate = 0.1;           // max correction per second of elapsed time
    double snap_threshold_s = 0.25;   // larger errors are corrected at once
};

class PlayoutClock {
public:
    explicit PlayoutClock(const PlayoutConfig& config = {});

    // A snapshot sampled at server_time_s arrived at local_time_s.
    void on_snapshot(double server_time_s, double local_time_s);
    // The server time to render at local_time_s. Call with non-decreasing local times.
    double render_time(double local_time_s);

    bool has_data() const { return has_data_; }
    double delay_s() const;
    // A server that sends a snapshot at every change of motion needs no interval in the delay
    // (the free motion is exact past the newest state): 0; otherwise 2.
    void set_interval_factor(double factor) { config_.interval_factor = factor; }
    double interval_s() const { return interval_s_; }
    double jitter_s() const { return jitter_s_; }
    double base_transit_s() const;
    // The render time the clock is steering towards (no smoothing).
    double target_time(double local_time_s) const;

private:
    PlayoutConfig config_;
    bool has_data_ = false;
    double last_server_s_ = 0.0;
    double last_arrival_s_ = 0.0;
    double interval_s_;
    double jitter_s_ = 0.0;
    std::deque<double> transits_;
    bool has_render_ = false;
    double last_local_s_ = 0.0;
    double last_render_s_ = 0.0;
};

} // namespace carrom::client
