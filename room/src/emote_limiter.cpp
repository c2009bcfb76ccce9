#include "carrom/room/emote_limiter.hpp"

#include <algorithm>

namespace carrom::room {

bool EmoteLimiter::try_take(std::int64_t now_ms) {
    const std::int64_t empty_at = used_ ? std::max(empty_at_ms_, now_ms) : now_ms;
    if (empty_at - now_ms > (kBurst - 1) * kIntervalMs) {
        return false;
    }
    empty_at_ms_ = empty_at + kIntervalMs;
    used_ = true;
    return true;
}

} // namespace carrom::room
