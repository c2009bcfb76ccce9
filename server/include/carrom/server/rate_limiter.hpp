#pragma once
// Token bucket per connection: `rate` messages per second sustained, bursts up to `burst`.
// A client that keeps sending while empty is disconnected once its rejected messages reach
// `burst` in a row.

#include <cstdint>

namespace carrom::server {

class RateLimiter {
public:
    RateLimiter(double rate_per_s, double burst, std::int64_t now_ms);

    enum class Verdict { Accept, Reject, Disconnect };
    Verdict on_message(std::int64_t now_ms);

private:
    double rate_per_ms_;
    double burst_;
    double tokens_;
    std::int64_t last_ms_;
    int rejected_in_a_row_ = 0;
};

} // namespace carrom::server
