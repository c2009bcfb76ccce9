#include "address_rate_limiter.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::server {

AddressRateLimiter::AddressRateLimiter(double rate_per_s, double burst, std::size_t max_addresses)
    : rate_per_s_(std::max(rate_per_s, 0.001)), burst_(std::max(burst, 1.0)),
      max_addresses_(std::max<std::size_t>(max_addresses, 1)) {}

void AddressRateLimiter::make_room(std::int64_t now_ms) {
    std::erase_if(buckets_, [now_ms](const auto& entry) { return entry.second.full(now_ms); });
    if (buckets_.size() < max_addresses_) {
        return;
    }
    const auto oldest = std::min_element(buckets_.begin(), buckets_.end(), [](auto& a, auto& b) {
        return a.second.last_ms() < b.second.last_ms();
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
        it = buckets_.emplace(address, TokenBucket(rate_per_s_, burst_, now_ms)).first;
    }
    TokenBucket& bucket = it->second;
    if (bucket.take(now_ms)) {
        return 0;
    }
    // Whole milliseconds (a rounding error of the division does not add a second), then seconds.
    const double wait_ms = std::ceil(bucket.ms_until_token(now_ms) - 1e-6);
    return std::max(1, static_cast<int>(std::ceil(wait_ms / 1000.0)));
}

std::size_t AddressRateLimiter::size() const {
    const std::lock_guard lock(mutex_);
    return buckets_.size();
}

} // namespace carrom::server
