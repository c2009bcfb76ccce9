#include "carrom/client/playout_clock.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

PlayoutClock::PlayoutClock(const PlayoutConfig& config)
    : config_(config), interval_s_(config.initial_interval_s) {}

void PlayoutClock::on_snapshot(double server_time_s, double local_time_s) {
    const double transit = local_time_s - server_time_s;
    if (has_data_) {
        const double gap = server_time_s - last_server_s_;
        if (gap > 0.0 && gap <= config_.gap_s) {
            interval_s_ += 0.1 * (gap - interval_s_); // EWMA of the server's snapshot spacing
        }
        const double since = std::max(local_time_s - last_arrival_s_, 0.0);
        jitter_s_ *= std::exp(-since / config_.jitter_decay_s);
    }
    transits_.push_back(transit);
    while (transits_.size() > config_.transit_window) {
        transits_.pop_front();
    }
    jitter_s_ = std::max(jitter_s_, transit - base_transit_s());
    last_server_s_ = server_time_s;
    last_arrival_s_ = local_time_s;
    has_data_ = true;
}

double PlayoutClock::base_transit_s() const {
    if (transits_.empty()) {
        return 0.0;
    }
    return *std::min_element(transits_.begin(), transits_.end());
}

double PlayoutClock::delay_s() const {
    const double d = config_.interval_factor * interval_s_ + jitter_s_;
    return std::clamp(d, config_.min_delay_s, config_.max_delay_s);
}

double PlayoutClock::target_time(double local_time_s) const {
    return local_time_s - base_transit_s() - delay_s();
}

double PlayoutClock::render_time(double local_time_s) {
    const double target = target_time(local_time_s);
    if (!has_render_) {
        has_render_ = true;
        last_local_s_ = local_time_s;
        last_render_s_ = target;
        return target;
    }
    const double elapsed = std::max(local_time_s - last_local_s_, 0.0);
    const double free_run = last_render_s_ + elapsed;
    const double error = target - free_run;
    double next = target; // a large error (a new match, a long stall) is corrected at once
    if (std::abs(error) <= config_.snap_threshold_s) {
        const double max_step = config_.slew_rate * elapsed;
        // Small corrections are slewed and never make the rendered time run backwards.
        next = std::max(free_run + std::clamp(error, -max_step, max_step), last_render_s_);
    }
    last_local_s_ = local_time_s;
    last_render_s_ = next;
    return next;
}

} // namespace carrom::client
