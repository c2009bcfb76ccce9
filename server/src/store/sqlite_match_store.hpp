#pragma once
// The embedded MatchStore: one SQLite file in WAL mode (docs/store.md).
//
// Threads: callers only queue; a writer thread (StoreWriteQueue, store_write_queue.hpp) takes up to
// max_batch items at a time and writes them in one transaction (SqliteWriter); a checkpointer
// thread copies the WAL into the database every checkpoint_interval on a connection of its own,
// so a commit never waits for an fsync. Reads use a third connection (SqliteReader).
//
// Durability: synchronous=NORMAL. A committed transaction is in the WAL file, that is in the
// operating system's cache, when its appends' on_written(true) run: a crash of the process
// (kill -9) loses nothing written; a power loss may lose what was committed since the last
// checkpoint (at most about checkpoint_interval plus the checkpoint's own time), and the file
// stays consistent.
//
// Failures (disk full, I/O error, the test seam): as StoreWriteQueue describes; items held in
// memory, in order, retried with backoff, the store degraded meanwhile.

#include "store/file_lock.hpp"
#include "store/match_store.hpp"
#include "store/queued_match_store.hpp"
#include "store/store_options.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace SQLite {
class Database;
} // namespace SQLite

namespace carrom::store {

namespace sqlite {
class SqlitePlayerReader;
class SqliteReader;
class SqliteWriter;
} // namespace sqlite

using SqliteStoreOptions = StoreOptions;

class SqliteMatchStore final : public QueuedMatchStore {
public:
    struct Opened {
        std::unique_ptr<SqliteMatchStore> store; // set when !error
        std::optional<StoreError> error;
    };
    // Opens (or creates) the database at path: prepare_database (sqlite_database.hpp) checks it,
    // locks it against a second server and migrates it; then the threads start. On error the
    // file is untouched and error holds one line for the operator.
    static Opened open(const std::string& path, SqliteStoreOptions options = {});

    // Writes what is queued (for up to close_timeout), stops the threads, checkpoints.
    ~SqliteMatchStore() override;

    Loaded<std::vector<RecoveredMatch>> load_unfinished() override;
    Loaded<std::optional<proto::MatchJournal>> journal(const MatchId& match) override;
    Loaded<std::vector<MatchListing>> recent_matches(const std::string& player, int limit) override;
    Loaded<std::vector<IdentifiedPlayer>> load_players() override;
    Loaded<std::optional<IdentifiedPlayer>> find_player(const std::string& name_key) override;
    Loaded<std::vector<PlayerRating>> player_ratings(const PlayerKeyHash& player) override;
    Loaded<std::vector<LeaderboardRow>> leaderboard(rules::RuleSet rule_set, int limit) override;

    const std::string& path() const { return path_; }

private:
    SqliteMatchStore(std::string path, FileLock lock, SqliteStoreOptions options);
    void checkpointer_loop();

    std::string path_;
    FileLock lock_;
    SqliteStoreOptions options_;
    std::unique_ptr<sqlite::SqliteWriter> writer_connection_;
    std::unique_ptr<sqlite::SqliteReader> reader_;
    std::unique_ptr<sqlite::SqlitePlayerReader> player_reader_;
    std::unique_ptr<SQLite::Database> checkpoint_connection_;
    std::atomic<std::uint64_t> commits_since_checkpoint_{0};

    std::mutex checkpoint_mutex_;
    std::condition_variable checkpoint_cv_;
    bool checkpoint_stop_ = false;
    std::thread checkpointer_;
};

} // namespace carrom::store
