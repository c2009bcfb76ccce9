#include "carrom/server/token_bucket.hpp"

#include <algorithm>

namespace carrom::server {

TokenBucket::TokenBucket(double rate_per_s, double capacity, std::int64_t now_ms)
    : rate_per_ms_(rate_per_s / 1000.0), capacity_(capacity), tokens_(capacity), last_ms_(now_ms) {}

double TokenBucket::tokens(std::int64_t now_ms) const {
    if (now_ms <= last_ms_) {
        return tokens_;
    }
    return std::min(capacity_, tokens_ + static_cast<double>(now_ms - last_ms_) * rate_per_ms_);
}

bool TokenBucket::take(std::int64_t now_ms) {
    tokens_ = tokens(now_ms);
    last_ms_ = std::max(last_ms_, now_ms);
    if (tokens_ < 1.0) {
        return false;
    }
    tokens_ -= 1.0;
    return true;
}

double TokenBucket::ms_until_token(std::int64_t now_ms) const {
    return std::max(0.0, (1.0 - tokens(now_ms)) / rate_per_ms_);
}

} // namespace carrom::server
