#pragma once
// Server counters, updated from any thread (relaxed atomics), rendered in the Prometheus text
// exposition format for GET /metrics: the rooms' own (room::RoomCounters) and the network's.

#include "carrom/room/room_counters.hpp"
#include "store/cluster.hpp"
#include "store/match_store.hpp"

#include <atomic>
#include <cstdint>
#include <string>

namespace carrom::server {

struct Metrics : room::RoomCounters {
    std::atomic<std::int64_t> connections{0};                // gauge: open WebSocket connections
    std::atomic<std::int64_t> connections_total{0};          // accepted WebSocket connections
    std::atomic<std::int64_t> rejected_connections_total{0}; // over max_connections
    std::atomic<std::int64_t> rooms{0};                      // gauge
    std::atomic<std::int64_t> messages_in_total{0};
    std::atomic<std::int64_t> messages_out_total{0};
    std::atomic<std::int64_t> bytes_in_total{0};
    std::atomic<std::int64_t> bytes_out_total{0};
    std::atomic<std::int64_t> snapshots_dropped_total{0}; // dropped for slow clients
    std::atomic<std::int64_t> cues_dropped_total{0};      // collision and aim cues dropped
    std::atomic<std::int64_t> slow_client_disconnects_total{0};
    std::atomic<std::int64_t> http_requests_total{0};
    std::atomic<std::int64_t> http_rate_limited_total{0};      // 429 answers
    std::atomic<std::int64_t> tls_handshakes_total{0};         // completed (https, wss)
    std::atomic<std::int64_t> tls_handshake_failures_total{0}; // refused, broken or timed out
    std::atomic<std::int64_t> redirects_total{0}; // redirect messages sent (cluster mode)

    std::string prometheus_text() const;
};

// The match store's metrics (carrom_store_errors_total, carrom_store_pending,
// carrom_store_written_total, carrom_store_degraded), all 0 without a store (health null).
std::string store_prometheus_text(const store::StoreHealth* health);

// Cluster mode (docs/cluster.md): carrom_cluster_info{instance,public_url},
// carrom_cluster_lease_ok, carrom_cluster_lease_expires_seconds, carrom_cluster_matches_owned,
// carrom_cluster_takeovers_total, carrom_cluster_matches_lost_total.
std::string cluster_prometheus_text(const store::ClusterStatus& status);
// /healthz's line in cluster mode: "cluster: {JSON}\n" with the same figures.
std::string cluster_health_line(const store::ClusterStatus& status);

} // namespace carrom::server
