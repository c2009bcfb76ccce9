#pragma once
// The one clock a room reads: milliseconds on a monotonic scale. Clients only ever see
// differences (deadline - server_time), so the origin does not matter. carrom-server uses
// SteadyClock; tests use ManualClock; the client's offline demo its own frame clock.

#include <atomic>
#include <cstdint>

namespace carrom::room {

class Clock {
public:
    virtual ~Clock() = default;
    virtual std::int64_t now_ms() const = 0;
};

// std::chrono::steady_clock in ms.
class SteadyClock final : public Clock {
public:
    std::int64_t now_ms() const override;
};

// Moves only when told to. Thread-safe reads.
class ManualClock final : public Clock {
public:
    explicit ManualClock(std::int64_t start_ms = 1000000) : now_(start_ms) {}
    std::int64_t now_ms() const override { return now_.load(); }
    void advance_ms(std::int64_t ms) { now_ += ms; }
    void set_ms(std::int64_t ms) { now_ = ms; }

private:
    std::atomic<std::int64_t> now_;
};

} // namespace carrom::room
