#pragma once
// The rate limit of one seat's emotes: a burst of kBurst, then one per kIntervalMs (the generic
// cell rate algorithm on the room's monotonic clock, in integer milliseconds, so it is exact and
// needs no timer). An emote over the limit is refused; nothing else about the seat changes.

#include <cstdint>

namespace carrom::room {

class EmoteLimiter {
public:
    static constexpr int kBurst = 3;                  // emotes accepted back to back
    static constexpr std::int64_t kIntervalMs = 2000; // then one per interval

    // True (and the emote is counted) when an emote at now_ms is within the limit.
    bool try_take(std::int64_t now_ms);

private:
    // The time at which the bucket is empty again: each accepted emote adds kIntervalMs. An emote
    // is accepted while this lies at most (kBurst - 1) intervals after now.
    std::int64_t empty_at_ms_ = 0;
    bool used_ = false; // false until the first emote (the clock may start anywhere)
};

} // namespace carrom::room
