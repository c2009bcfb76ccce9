#pragma once
// The one clock a room reads: milliseconds on a monotonic scale. Clients only ever see
// differences (deadline - server_time), so the origin does not matter. carrom-server uses
// SteadyClock; tests use ManualClock; the client's offline demo its own frame clock.
//
// Journals (journal_sink.hpp) record wall-clock times, Unix time in ms: unix_ms(). By default it
// reads std::chrono::system_clock; ManualClock returns now_ms(), so tests stay deterministic.

#include <atomic>
#include <cstdint>

namespace carrom::room {

class Clock {
public:
    virtual ~Clock() = default;
    virtual std::int64_t now_ms() const = 0;
    virtual std::int64_t unix_ms() const;
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
    std::int64_t unix_ms() const override { return now_.load(); }
    void advance_ms(std::int64_t ms) { now_ += ms; }
    void set_ms(std::int64_t ms) { now_ = ms; }

private:
    std::atomic<std::int64_t> now_;
};

} // namespace carrom::room
