#pragma once
// Rate limit per connection: a TokenBucket of `rate` messages per second sustained, bursts up to
// `burst`. A client that keeps sending over the rate is disconnected once its rejected messages
// reach `burst`; the count starts again only when the client was quiet long enough for the
// bucket to refill completely. Accepted messages in between (one per 1/rate s during a flood) do
// not reset it, so how fast the server happens to read a flood does not decide whether it closes.

#include "carrom/server/token_bucket.hpp"

#include <cstdint>

namespace carrom::server {

class RateLimiter {
public:
    RateLimiter(double rate_per_s, double burst, std::int64_t now_ms);

    enum class Verdict { Accept, Reject, Disconnect };
    Verdict on_message(std::int64_t now_ms);

private:
    TokenBucket bucket_;
    double burst_;
    int rejected_ = 0; // rejected messages since the bucket was last full
};

} // namespace carrom::server
