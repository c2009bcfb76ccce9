#pragma once
// The networked MatchStore: a PostgreSQL database (docs/store.md, "The PostgreSQL backend"),
// opened by URL (postgresql://USER@HOST[:PORT]/DB, postgres://..., or with ?host=/socket/dir).
//
// Threads: callers only queue; the StoreWriteQueue's writer thread (store_write_queue.hpp) writes
// up to max_batch items at a time in one transaction on its own connection (PostgresWriter); reads
// run on the calling thread on a second connection (PostgresReader). No libpq call runs on a
// caller's thread except the reads, which may block (the server calls them off its I/O threads).
//
// Durability: an append's on_written(true) runs after its transaction's COMMIT returned, so the
// entry is as durable as the server's synchronous_commit makes it (on: flushed to its WAL).
//
// Failures (the server down or restarting, the network cut, the test seam): as StoreWriteQueue
// describes; items held in memory, in order, retried with backoff, the store degraded meanwhile.
// Each retry connects again if the connection broke. A COMMIT whose outcome is unknown (the
// connection broke during it) is retried too: whatever of it was written is then refused as
// written twice (dropped and counted), so nothing is stored twice.
//
// One server per database: in single-instance mode the write connection holds a session
// advisory lock (postgres_database.hpp, kLockKey); a second server is refused (store_locked).
//
// Cluster mode (open_cluster, docs/cluster.md): several servers on one database, no lock; each
// match is written only by the instance that owns it (PostgresWriter), the instance keeps a
// lease and takes over the matches of dead instances (PostgresCluster, cluster()), and
// load_unfinished claims the matches to recover instead of reading them all.

#include "store/match_ownership.hpp"
#include "store/match_store.hpp"
#include "store/postgres_cluster.hpp"
#include "store/queued_match_store.hpp"
#include "store/store_options.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace carrom::store {

namespace postgres {
class PostgresReader;
class PostgresWriter;
} // namespace postgres

class PostgresMatchStore final : public QueuedMatchStore {
public:
    struct Opened {
        std::unique_ptr<PostgresMatchStore> store; // set when !error
        std::optional<StoreError> error;
    };
    // Connects, checks and migrates the database (postgres_database.hpp) and, with hold_lock,
    // takes the one-server lock; then the writer starts. On error error holds one line for the
    // operator and nothing was written.
    static Opened open(const std::string& url, StoreOptions options = {}, bool hold_lock = true);
    // Cluster mode: registers the instance (postgres_cluster.hpp; cluster_instance_in_use when
    // another live process has its id) instead of taking the lock.
    static Opened open_cluster(const std::string& url, postgres::ClusterOptions cluster,
                               StoreOptions options = {});

    // Writes what is queued (for up to close_timeout), stops the writer, ends the lease (cluster
    // mode), disconnects.
    ~PostgresMatchStore() override;

    // Cluster mode: the matches this instance claims (its own id's and the orphans), see
    // PostgresCluster::claim.
    Loaded<std::vector<RecoveredMatch>> load_unfinished() override;
    Cluster* cluster() override { return cluster_.get(); }
    Loaded<std::optional<proto::MatchJournal>> journal(const MatchId& match) override;
    Loaded<std::vector<MatchListing>> recent_matches(const std::string& player, int limit) override;
    Loaded<std::vector<IdentifiedPlayer>> load_players() override;
    Loaded<std::optional<IdentifiedPlayer>> find_player(const std::string& name_key) override;
    Loaded<std::vector<PlayerRating>> player_ratings(const PlayerKeyHash& player) override;
    Loaded<std::vector<LeaderboardRow>> leaderboard(rules::RuleSet rule_set, int limit) override;

    // The URL with its password hidden.
    const std::string& shown_url() const { return shown_; }

private:
    PostgresMatchStore(std::string shown, StoreOptions options);
    // Checks the URL, makes the store, opens its writer (and cluster) with open_writer, then the
    // reader, and starts the writer thread.
    static Opened
    open_with(const std::string& url, StoreOptions options,
              const std::function<std::optional<StoreError>(PostgresMatchStore&)>& open_writer);

    std::string shown_;
    StoreOptions options_;
    std::unique_ptr<postgres::PostgresWriter> writer_;
    std::unique_ptr<postgres::PostgresReader> reader_;
    std::unique_ptr<postgres::PostgresCluster> cluster_; // cluster mode only
};

} // namespace carrom::store
