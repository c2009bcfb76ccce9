#include "carrom/server/rate_limiter.hpp"

#include <algorithm>

namespace carrom::server {

RateLimiter::RateLimiter(double rate_per_s, double burst, std::int64_t now_ms)
    : rate_per_ms_(rate_per_s / 1000.0), burst_(burst), tokens_(burst), last_ms_(now_ms) {}

RateLimiter::Verdict RateLimiter::on_message(std::int64_t now_ms) {
    if (now_ms > last_ms_) {
        tokens_ = std::min(burst_, tokens_ + static_cast<double>(now_ms - last_ms_) * rate_per_ms_);
        last_ms_ = now_ms;
    }
    if (tokens_ >= burst_) {
        rejected_ = 0; // quiet long enough to refill the bucket: earlier excess is forgiven
    }
    if (tokens_ >= 1.0) {
        tokens_ -= 1.0;
        return Verdict::Accept;
    }
    ++rejected_;
    return static_cast<double>(rejected_) >= burst_ ? Verdict::Disconnect : Verdict::Reject;
}

} // namespace carrom::server
