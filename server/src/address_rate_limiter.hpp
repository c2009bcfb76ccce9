#pragma once
// Private to server/src: a TokenBucket per client address for plain HTTP requests (the match
// API and /metrics): rate_per_s requests per second sustained, bursts up to burst. The table
// holds at most max_addresses buckets: a new address in a full table first evicts every bucket
// that has refilled (an idle address: forgetting it changes nothing), else the least recently
// used one. Thread-safe (one mutex); times are the caller's monotonic milliseconds. Boost-free.

#include "carrom/server/token_bucket.hpp"

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_map>

namespace carrom::server {

class AddressRateLimiter {
public:
    AddressRateLimiter(double rate_per_s, double burst, std::size_t max_addresses);

    // Takes a token for address: 0 when the request may go on, otherwise the whole seconds
    // (at least 1) until the address has a token again (the Retry-After of a 429).
    int take(const std::string& address, std::int64_t now_ms);
    // Addresses in the table.
    std::size_t size() const;

private:
    void make_room(std::int64_t now_ms);

    double rate_per_s_;
    double burst_;
    std::size_t max_addresses_;
    mutable std::mutex mutex_;
    std::unordered_map<std::string, TokenBucket> buckets_;
};

} // namespace carrom::server
