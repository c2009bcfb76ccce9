#pragma once
// Every server setting, with the defaults of the command line (see docs/server.md).

#include "carrom/proto/types.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace carrom::server {

struct ServerSettings {
    std::string host = "127.0.0.1";
    std::uint16_t port = 7777;            // 0 = ephemeral (the bound port is printed)
    int threads = 2;                      // I/O threads
    double snapshot_hz = 10.0;            // regular snapshots per second while pieces move
    bool contact_snapshots = true;        // plus a snapshot at every change of motion
    double time_scale = 1.0;              // match seconds per wall second (tests speed play up)
    std::size_t max_message_bytes = 4096; // client text frame limit
    double max_rate = 30.0;               // client messages per second (sustained)
    double rate_burst = 60.0;             // bucket size
    double handshake_timeout_s = 10.0;    // WebSocket upgrade + hello
    double idle_timeout_s = 60.0;         // nothing received (keep-alive pings at half of it)
    int max_connections = 10000;
    int max_connections_per_address = 32; // open WebSocket connections from one client address
    // Proxies (addresses or networks) whose X-Forwarded-For names the client address that the
    // per-address limits count (docs/server.md, "Behind a proxy"); empty: none.
    std::vector<std::string> trusted_proxies;
    int max_rooms = 5000;
    double grace_s = 60.0;          // dropped seat kept this long
    double shot_clock_s = 20.0;     // default per stroke; 0 = off
    double bot_shot_clock_s = 40.0; // default per stroke with a server bot (at least the above)
    std::size_t max_queue_bytes = 1 << 20; // per-session write queue bound
    std::size_t snapshot_backlog = 8;      // waiting snapshots at which new ones are dropped
    double shutdown_grace_s = 3.0;         // SIGINT/SIGTERM: time to close cleanly
    // A quick-match waiter with no partner after this long gets a bot room; 0 = never.
    double quick_match_bot_s = 20.0;
    proto::BotLevel quick_match_bot_level = proto::BotLevel::Medium;
    // Plain HTTP requests to the match API and /metrics per client address (429 over it).
    double http_rate = 10.0;                // requests per second (sustained)
    double http_burst = 20.0;               // bucket size
    std::size_t http_rate_addresses = 4096; // addresses tracked at once
    // TLS (https, wss) on the same port as plain http and ws, when both files are given (PEM;
    // docs/tls.md). Empty: plain only.
    std::string tls_cert;
    std::string tls_key;
    double tls_handshake_timeout_s = 5.0; // the first bytes and the whole TLS handshake
};

} // namespace carrom::server
