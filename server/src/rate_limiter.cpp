#include "carrom/server/rate_limiter.hpp"

namespace carrom::server {

RateLimiter::RateLimiter(double rate_per_s, double burst, std::int64_t now_ms)
    : bucket_(rate_per_s, burst, now_ms), burst_(burst) {}

RateLimiter::Verdict RateLimiter::on_message(std::int64_t now_ms) {
    if (bucket_.full(now_ms)) {
        rejected_ = 0; // quiet long enough to refill the bucket: earlier excess is forgiven
    }
    if (bucket_.take(now_ms)) {
        return Verdict::Accept;
    }
    ++rejected_;
    return static_cast<double>(rejected_) >= burst_ ? Verdict::Disconnect : Verdict::Reject;
}

} // namespace carrom::server
