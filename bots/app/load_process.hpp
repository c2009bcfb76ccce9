#pragma once
// The carrom-server that carrom-load measures: starting one on 127.0.0.1, and reading its memory,
// CPU time and /metrics.

#include <sys/types.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace carrom::load {

struct SpawnedServer {
    pid_t pid = -1;
    std::uint16_t port = 0;
};

// Starts the server on 127.0.0.1 with an ephemeral port (and --data none unless `extra` names
// --data) and reads its "listening on" line; its stdout is drained from then on.
std::optional<SpawnedServer> spawn_server(const std::string& binary,
                                          const std::vector<std::string>& extra);

// VmRSS of a process, KiB (0 if unreadable).
long rss_kib(pid_t pid);

// utime + stime of a process, seconds.
double cpu_seconds(pid_t pid);

// GET /metrics of the server on 127.0.0.1:port as name -> value (histogram buckets keep their
// label in the name); empty when it cannot be read.
std::map<std::string, double> fetch_metrics(std::uint16_t port);

} // namespace carrom::load
