#pragma once
// When to try again after a connection that held a seat was lost: exponential back-off with
// jitter, for as long as the server holds the seat. Shared by carrom-bot and carrom-client.
//
// The n-th try (n = 1, 2, ...) waits a delay drawn uniformly from [d/2, d], where
// d = min(first * 2^(n-1), cap): with the defaults 125-250 ms, 250-500 ms, ... up to 2.5-5 s.
// The tries stop once `give_up_after` has passed since the loss.

#include <chrono>
#include <cstdint>
#include <random>

namespace carrom::net {

struct BackoffSettings {
    std::chrono::milliseconds first{250};
    std::chrono::milliseconds cap{5000};
    // How long after the loss to keep trying: the server's grace period (default 60 s) plus a
    // margin for clocks and the last try's connect time.
    std::chrono::milliseconds give_up_after{130000};
};

class Backoff {
public:
    using Clock = std::chrono::steady_clock;

    explicit Backoff(BackoffSettings settings = {}, std::uint64_t seed = std::random_device{}());

    // The connection was lost at `now`: counting starts again.
    void start(Clock::time_point now);
    // The wait before the next try (counts the try).
    std::chrono::milliseconds next_delay();
    // Tries counted since start().
    int tries() const { return tries_; }
    // The loss was longer ago than give_up_after.
    bool expired(Clock::time_point now) const { return now >= lost_at_ + settings_.give_up_after; }
    Clock::time_point lost_at() const { return lost_at_; }
    const BackoffSettings& settings() const { return settings_; }

private:
    BackoffSettings settings_;
    std::mt19937_64 random_;
    Clock::time_point lost_at_{};
    int tries_ = 0;
};

} // namespace carrom::net
