#include "carrom/net/backoff.hpp"

#include <algorithm>

namespace carrom::net {

Backoff::Backoff(BackoffSettings settings, std::uint64_t seed)
    : settings_(settings), random_(seed) {}

void Backoff::start(Clock::time_point now) {
    lost_at_ = now;
    tries_ = 0;
}

std::chrono::milliseconds Backoff::next_delay() {
    const int doublings = std::min(tries_, 30);
    ++tries_;
    const auto first = std::max<std::int64_t>(settings_.first.count(), 1);
    const auto cap = std::max<std::int64_t>(settings_.cap.count(), first);
    std::int64_t d = first;
    for (int i = 0; i < doublings && d < cap; ++i) {
        d *= 2;
    }
    d = std::min(d, cap);
    std::uniform_int_distribution<std::int64_t> draw(d / 2, d);
    return std::chrono::milliseconds(draw(random_));
}

} // namespace carrom::net
