#pragma once
// Server counters, updated from any thread (relaxed atomics), rendered in the Prometheus text
// exposition format for GET /metrics.

#include <array>
#include <atomic>
#include <cstdint>
#include <string>

namespace carrom::server {

struct Metrics {
    std::atomic<std::int64_t> connections{0};                // gauge: open WebSocket connections
    std::atomic<std::int64_t> connections_total{0};          // accepted WebSocket connections
    std::atomic<std::int64_t> rejected_connections_total{0}; // over max_connections
    std::atomic<std::int64_t> rooms{0};                      // gauge
    std::atomic<std::int64_t> matches{0};                    // gauge: rooms with a game in progress
    std::atomic<std::int64_t> matches_started_total{0};
    std::atomic<std::int64_t> matches_finished_total{0};
    std::atomic<std::int64_t> shots_total{0};
    std::atomic<std::int64_t> messages_in_total{0};
    std::atomic<std::int64_t> messages_out_total{0};
    std::atomic<std::int64_t> bytes_in_total{0};
    std::atomic<std::int64_t> bytes_out_total{0};
    std::atomic<std::int64_t> errors_sent_total{0};
    std::atomic<std::int64_t> snapshots_total{0};         // snapshot broadcasts
    std::atomic<std::int64_t> snapshots_dropped_total{0}; // dropped for slow clients
    std::atomic<std::int64_t> cues_dropped_total{0};      // collision and aim cues dropped
    std::atomic<std::int64_t> slow_client_disconnects_total{0};
    std::atomic<std::int64_t> http_requests_total{0};

    // Snapshot send lag (actual send time - scheduled time), ms. Bucket upper bounds below.
    static constexpr std::array<double, 8> kLagBucketsMs{0.5, 1, 2, 5, 10, 20, 50, 100};
    std::array<std::atomic<std::int64_t>, kLagBucketsMs.size()> lag_buckets{};
    std::atomic<std::int64_t> lag_count{0};
    std::atomic<std::int64_t> lag_sum_us{0};
    void observe_snapshot_lag_ms(double lag_ms);

    std::string prometheus_text() const;
};

} // namespace carrom::server
