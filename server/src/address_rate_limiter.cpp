#include "address_rate_limiter.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace carrom::server {

AddressRateLimiter::AddressRateLimiter(double rate_per_s, double burst, std::size_t max_addresses)
    : rate_per_ms_(std::max(rate_per_s, 0.001) / 1000.0), burst_(std::max(burst, 1.0)),
      max_addresses_(std::max<std::size_t>(max_addresses, 1)) {}

void AddressRateLimiter::refill(Bucket& bucket, std::int64_t now_ms) const {
    if (now_ms > bucket.last_ms) {
        bucket.tokens = std::min(
            burst_, bucket.tokens + static_cast<double>(now_ms - bucket.last_ms) * rate_per_ms_);
        bucket.last_ms = now_ms;
    }
}

void AddressRateLimiter::make_room(std::int64_t now_ms) {
    for (auto it = buckets_.begin(); it != buckets_.end();) {
        refill(it->second, now_ms);
        it = it->second.tokens >= burst_ ? buckets_.erase(it) : std::next(it);
    }
    if (buckets_.size() < max_addresses_) {
        return;
    }
    const auto oldest = std::min_element(buckets_.begin(), buckets_.end(), [](auto& a, auto& b) {
        return a.second.last_ms < b.second.last_ms;
    });
    buckets_.erase(oldest);
}

int AddressRateLimiter::take(const std::string& address, std::int64_t now_ms) {
    const std::lock_guard lock(mutex_);
    auto it = buckets_.find(address);
    if (it == buckets_.end()) {
        if (buckets_.size() >= max_addresses_) {
            make_room(now_ms);
        }
        it = buckets_.emplace(address, Bucket{burst_, now_ms}).first;
    }
    Bucket& bucket = it->second;
    refill(bucket, now_ms);
    if (bucket.tokens >= 1.0) {
        bucket.tokens -= 1.0;
        return 0;
    }
    // Whole milliseconds (a rounding error of the division does not add a second), then seconds.
    const double wait_ms = std::ceil((1.0 - bucket.tokens) / rate_per_ms_ - 1e-6);
    return std::max(1, static_cast<int>(std::ceil(wait_ms / 1000.0)));
}

std::size_t AddressRateLimiter::size() const {
    const std::lock_guard lock(mutex_);
    return buckets_.size();
}

} // namespace carrom::server
