#include "carrom/server/metrics.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace carrom::server {

namespace {

void metric(std::ostringstream& out, const char* name, const char* type, const char* help,
            const std::atomic<std::int64_t>& value) {
    out << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n'
        << name << ' ' << value.load(std::memory_order_relaxed) << '\n';
}

std::string bucket_label(double bound) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", bound / 1000.0);
    return text;
}

} // namespace

std::string Metrics::prometheus_text() const {
    std::ostringstream out;
    metric(out, "carrom_connections", "gauge", "Open WebSocket connections.", connections);
    metric(out, "carrom_connections_total", "counter", "Accepted WebSocket connections.",
           connections_total);
    metric(out, "carrom_rejected_connections_total", "counter",
           "Connections refused at the connection limit.", rejected_connections_total);
    metric(out, "carrom_rooms", "gauge", "Open rooms.", rooms);
    metric(out, "carrom_matches", "gauge", "Rooms with a game in progress.", matches);
    metric(out, "carrom_matches_started_total", "counter", "Games started.", matches_started_total);
    metric(out, "carrom_matches_finished_total", "counter", "Games finished.",
           matches_finished_total);
    metric(out, "carrom_shots_total", "counter", "Shots played.", shots_total);
    metric(out, "carrom_messages_in_total", "counter", "Messages received.", messages_in_total);
    metric(out, "carrom_messages_out_total", "counter", "Messages sent.", messages_out_total);
    metric(out, "carrom_bytes_in_total", "counter", "Payload bytes received.", bytes_in_total);
    metric(out, "carrom_bytes_out_total", "counter", "Payload bytes sent.", bytes_out_total);
    metric(out, "carrom_errors_sent_total", "counter", "Error messages sent.", errors_sent_total);
    metric(out, "carrom_snapshots_total", "counter", "Snapshot broadcasts.", snapshots_total);
    metric(out, "carrom_snapshots_dropped_total", "counter", "Snapshots dropped for slow clients.",
           snapshots_dropped_total);
    metric(out, "carrom_cues_dropped_total", "counter",
           "Collision and aim cues dropped for clients that were behind.", cues_dropped_total);
    metric(out, "carrom_slow_client_disconnects_total", "counter",
           "Clients disconnected for a full write queue.", slow_client_disconnects_total);
    metric(out, "carrom_http_requests_total", "counter", "Plain HTTP requests.",
           http_requests_total);
    metric(out, "carrom_http_rate_limited_total", "counter",
           "HTTP requests refused with 429 (per-address rate limit).", http_rate_limited_total);
    metric(out, "carrom_tls_handshakes_total", "counter", "Completed TLS handshakes.",
           tls_handshakes_total);
    metric(out, "carrom_tls_handshake_failures_total", "counter",
           "TLS handshakes that failed or timed out.", tls_handshake_failures_total);
    metric(out, "carrom_redirects_total", "counter",
           "Clients sent to another instance of the cluster (redirect).", redirects_total);
    out << "# HELP carrom_snapshot_lag_seconds Snapshot send time minus its scheduled time.\n"
        << "# TYPE carrom_snapshot_lag_seconds histogram\n";
    for (std::size_t i = 0; i < kLagBucketsMs.size(); ++i) {
        out << "carrom_snapshot_lag_seconds_bucket{le=\"" << bucket_label(kLagBucketsMs[i])
            << "\"} " << lag_buckets[i].load(std::memory_order_relaxed) << '\n';
    }
    const auto count = lag_count.load(std::memory_order_relaxed);
    char sum[32];
    std::snprintf(sum, sizeof sum, "%.6f",
                  static_cast<double>(lag_sum_us.load(std::memory_order_relaxed)) / 1e6);
    out << "carrom_snapshot_lag_seconds_bucket{le=\"+Inf\"} " << count << '\n'
        << "carrom_snapshot_lag_seconds_sum " << sum << '\n'
        << "carrom_snapshot_lag_seconds_count " << count << '\n';
    return out.str();
}

std::string store_prometheus_text(const store::StoreHealth* health) {
    const store::StoreHealth none;
    const store::StoreHealth& h = health != nullptr ? *health : none;
    std::ostringstream out;
    const auto line = [&](const char* name, const char* type, const char* help,
                          std::uint64_t value) {
        out << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n'
            << name << ' ' << value << '\n';
    };
    line("carrom_store_errors_total", "counter",
         "Failed match store write attempts, and items dropped.", h.errors_total);
    line("carrom_store_pending", "gauge", "Match store items queued or being written.", h.pending);
    line("carrom_store_written_total", "counter", "Match store items written.", h.written_total);
    line("carrom_store_degraded", "gauge", "1 while match store writes fail.",
         h.degraded ? 1U : 0U);
    if (!h.backend.empty()) {
        out << "# HELP carrom_store_info The match store's backend.\n"
               "# TYPE carrom_store_info gauge\ncarrom_store_info{backend=\""
            << h.backend << "\"} 1\n";
    }
    return out.str();
}

std::string cluster_prometheus_text(const store::ClusterStatus& status) {
    std::ostringstream out;
    const auto line = [&](const char* name, const char* type, const char* help,
                          std::int64_t value) {
        out << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n'
            << name << ' ' << value << '\n';
    };
    // The id and URL are checked at start ([A-Za-z0-9._-], a ws:// URL without quotes).
    out << "# HELP carrom_cluster_info This instance of the cluster.\n"
           "# TYPE carrom_cluster_info gauge\ncarrom_cluster_info{instance=\""
        << status.instance_id << "\",public_url=\"" << status.public_url << "\"} 1\n";
    line("carrom_cluster_lease_ok", "gauge", "1 while the instance's last lease renewal succeeded.",
         status.lease_ok ? 1 : 0);
    line("carrom_cluster_lease_expires_seconds", "gauge",
         "Unix time the lease expires at, by the database's clock.",
         status.lease_expires_ms / 1000);
    line("carrom_cluster_matches_owned", "gauge", "Unfinished matches this instance owns.",
         static_cast<std::int64_t>(status.matches_owned));
    line("carrom_cluster_takeovers_total", "counter",
         "Matches this instance claimed from an instance whose lease expired.",
         static_cast<std::int64_t>(status.takeovers_total));
    line("carrom_cluster_matches_lost_total", "counter",
         "Matches another instance claimed from this one.",
         static_cast<std::int64_t>(status.matches_lost_total));
    return out.str();
}

std::string cluster_health_line(const store::ClusterStatus& status) {
    const nlohmann::json j = {{"instance", status.instance_id},
                              {"public_url", status.public_url},
                              {"lease_ok", status.lease_ok},
                              {"lease_expires_ms", status.lease_expires_ms},
                              {"matches_owned", status.matches_owned},
                              {"takeovers_total", status.takeovers_total},
                              {"matches_lost_total", status.matches_lost_total}};
    return "cluster: " + j.dump() + "\n";
}

} // namespace carrom::server
