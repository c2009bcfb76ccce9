#pragma once
// The counters a Room updates: games, shots, snapshots and their send lag, errors sent. Updated
// from any thread (relaxed atomics). The server's Metrics extends them with its own counters and
// renders them for GET /metrics; the client's offline demo keeps its own, unread.

#include <array>
#include <atomic>
#include <cstdint>

namespace carrom::room {

struct RoomCounters {
    std::atomic<std::int64_t> matches{0}; // gauge: rooms with a game in progress
    std::atomic<std::int64_t> matches_started_total{0};
    std::atomic<std::int64_t> matches_finished_total{0};
    std::atomic<std::int64_t> shots_total{0};
    std::atomic<std::int64_t> errors_sent_total{0};
    std::atomic<std::int64_t> snapshots_total{0}; // snapshot broadcasts

    // Snapshot send lag (actual send time - scheduled time), ms. Bucket upper bounds below.
    static constexpr std::array<double, 8> kLagBucketsMs{0.5, 1, 2, 5, 10, 20, 50, 100};
    std::array<std::atomic<std::int64_t>, kLagBucketsMs.size()> lag_buckets{};
    std::atomic<std::int64_t> lag_count{0};
    std::atomic<std::int64_t> lag_sum_us{0};
    void observe_snapshot_lag_ms(double lag_ms);
};

} // namespace carrom::room
