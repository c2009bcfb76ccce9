#pragma once
// A token bucket: holds up to `capacity` tokens, earns `rate_per_s` tokens per second and
// starts full. Time is the caller's monotonic clock in milliseconds, passed to every call (the
// server's injectable room::Clock); the bucket never reads a clock of its own. A time earlier
// than the last one seen earns nothing and does not move the bucket's time back. Not
// thread-safe. Boost-free.

#include <cstdint>

namespace carrom::server {

class TokenBucket {
public:
    TokenBucket(double rate_per_s, double capacity, std::int64_t now_ms);

    // Takes one token at now_ms: true if the bucket held at least one.
    bool take(std::int64_t now_ms);
    // The tokens the bucket holds at now_ms (at most the capacity); changes nothing.
    double tokens(std::int64_t now_ms) const;
    // Whether the bucket has refilled to its capacity at now_ms.
    bool full(std::int64_t now_ms) const { return tokens(now_ms) >= capacity_; }
    // Milliseconds from now_ms until the bucket holds one token (0 if it holds one already).
    double ms_until_token(std::int64_t now_ms) const;
    // The latest time the bucket has seen, ms.
    std::int64_t last_ms() const { return last_ms_; }

private:
    double rate_per_ms_;
    double capacity_;
    double tokens_; // at last_ms_
    std::int64_t last_ms_;
};

} // namespace carrom::server
