#include "carrom/client/server_clock.hpp"

#include <algorithm>

namespace carrom::client {
namespace {
constexpr std::size_t kWindow = 8;
}

void ServerClock::one_way(std::int64_t server_ms, double local_s) {
    if (!samples_.empty()) {
        return; // round-trip samples are better
    }
    offset_ms_ = static_cast<double>(server_ms) - local_s * 1000.0;
}

void ServerClock::round_trip(std::int64_t server_ms, double sent_local_s, double local_s) {
    const double rtt = std::max(local_s - sent_local_s, 0.0) * 1000.0;
    const double mid_local_ms = (sent_local_s * 1000.0 + local_s * 1000.0) / 2.0;
    samples_.push_back({static_cast<double>(server_ms) - mid_local_ms, rtt});
    while (samples_.size() > kWindow) {
        samples_.pop_front();
    }
    rtt_ms_ = rtt;
    const auto best =
        std::min_element(samples_.begin(), samples_.end(),
                         [](const Sample& a, const Sample& b) { return a.rtt_ms < b.rtt_ms; });
    offset_ms_ = best->offset_ms;
}

double ServerClock::server_now_ms(double local_s) const {
    return local_s * 1000.0 + offset_ms_.value_or(0.0);
}

double seconds_until(const ServerClock& clock, std::int64_t deadline_ms, double local_s) {
    const double left_ms = static_cast<double>(deadline_ms) - clock.server_now_ms(local_s);
    return std::max(left_ms / 1000.0, 0.0);
}

} // namespace carrom::client
