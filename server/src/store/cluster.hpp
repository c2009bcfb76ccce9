#pragma once
// Cluster mode (docs/cluster.md): several carrom-server instances on one PostgreSQL store. The
// store's side of it, as the server sees it: the instance's lease, the matches it owns, takeovers
// of the matches of instances whose lease expired, and the news that a match was lost to another
// instance. MatchStore::cluster() gives it (null for a store without cluster mode: SQLite).
//
// Threads: the cluster's own thread renews the lease, checks ownership and claims orphaned
// matches (all the blocking database calls); the handlers run on it (on_lost also on the store's
// writer thread). Keep them short; never call the store's writes from them.

#include "store/match_store.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace carrom::store {

// What /healthz and /metrics show of the instance.
struct ClusterStatus {
    std::string instance_id;
    std::string public_url;
    bool lease_ok = false;                // the last renewal succeeded and its expiry is ahead
    std::int64_t lease_expires_ms = 0;    // Unix ms, by the database's clock, at the last renewal
    std::size_t matches_owned = 0;        // matches this instance writes (unfinished)
    std::uint64_t takeovers_total = 0;    // matches claimed from another instance (or from none)
    std::uint64_t matches_lost_total = 0; // matches another instance claimed from this one
};

struct ClusterHandlers {
    // Matches this instance has just claimed (takeover), each with its journal and seat tokens,
    // to run from where the journal ends. Called on the cluster thread.
    std::function<void(std::vector<RecoveredMatch>)> on_claimed;
    // A match of this instance that another instance claimed: write nothing more to it, stop
    // its room. Called once per match, on the cluster thread or the store's writer thread,
    // before the failed write's on_written(false) of a stroke that found it lost.
    std::function<void(const MatchId& match, const std::string& room_code)> on_lost;
};

class Cluster {
public:
    virtual ~Cluster() = default;
    // Starts the cluster thread: lease renewals, ownership checks and takeovers, every
    // renew_interval. Call once, after the matches load_unfinished gave are restored.
    virtual void start(ClusterHandlers handlers) = 0;
    // Stops the thread (idempotent). The lease is ended (expired now) when the store closes,
    // once its writes are flushed, so that the other instances claim its matches at once.
    virtual void stop() = 0;
    virtual ClusterStatus status() const = 0;
};

} // namespace carrom::store
