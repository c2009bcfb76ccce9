#pragma once
// The embedded MatchStore: one SQLite file in WAL mode (docs/store.md).
//
// Threads: callers only queue (a mutex held for a push). A writer thread takes up to max_batch
// items at a time and writes them in one transaction (SqliteWriter); a checkpointer thread copies
// the WAL into the database every checkpoint_interval on a connection of its own, so a commit
// never waits for an fsync. Reads use a third connection (SqliteReader).
//
// Durability: synchronous=NORMAL. A committed transaction is in the WAL file, that is in the
// operating system's cache, when its appends' on_written(true) run: a crash of the process
// (kill -9) loses nothing written; a power loss may lose what was committed since the last
// checkpoint (at most about checkpoint_interval plus the checkpoint's own time), and the file
// stays consistent.
//
// Failures: a transaction that fails (disk full, I/O error, the test seam) is rolled back; its
// items stay in memory, in order, in front of everything queued after them, and are retried
// with exponential backoff (retry_initial doubling up to retry_max). Until a retry succeeds the
// store is degraded (health()); every failed attempt counts in errors_total; the log gets one
// line at the first failure and at most one per log_interval after it, and one when writing
// resumes. Items beyond max_pending are dropped (counted). An item the database refuses as
// invalid (an append to a match never created, a seq written twice) is dropped and counted too.

#include "store/file_lock.hpp"
#include "store/match_store.hpp"
#include "store/write_item.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
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

struct SqliteStoreOptions {
    std::size_t max_batch = 512;      // items per transaction
    std::size_t max_pending = 200000; // items held (queued or failing); more are dropped
    std::chrono::milliseconds retry_initial{100};
    std::chrono::milliseconds retry_max{5000};
    std::chrono::milliseconds checkpoint_interval{1000};
    std::chrono::milliseconds close_timeout{5000}; // the destructor's time to write the queue
    std::chrono::milliseconds log_interval{10000}; // at most one write-error line per interval
    // Test seam: while it returns true, every transaction fails just before its COMMIT and is
    // rolled back, as a real write error would be. Called on the writer thread.
    std::function<bool()> fail_writes;
    // Test seam: called before each journal and recent_matches read, on the reading thread (it
    // may block, to make a read slow).
    std::function<void()> before_read;
};

class SqliteMatchStore final : public MatchStore {
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

    void create(proto::MatchCreated created) override;
    void append(const MatchId& match, std::int64_t seq, proto::JournalEntry entry,
                OnWritten on_written = {}) override;
    void set_seat_token(const MatchId& match, int seat, std::optional<TokenHash> token) override;
    void mark_finished(const MatchId& match, std::int64_t time_ms) override;
    void save_player(IdentifiedPlayer player) override;
    void set_rated_seat(const MatchId& match, int seat, PlayerKeyHash player) override;
    bool flush(std::chrono::milliseconds timeout) override;

    Loaded<std::vector<RecoveredMatch>> load_unfinished() override;
    Loaded<std::optional<proto::MatchJournal>> journal(const MatchId& match) override;
    Loaded<std::vector<MatchListing>> recent_matches(const std::string& player, int limit) override;
    Loaded<std::vector<IdentifiedPlayer>> load_players() override;
    Loaded<std::optional<IdentifiedPlayer>> find_player(const std::string& name_key) override;
    Loaded<std::vector<PlayerRating>> player_ratings(const PlayerKeyHash& player) override;
    Loaded<std::vector<LeaderboardRow>> leaderboard(rules::RuleSet rule_set, int limit) override;

    StoreHealth health() const override;
    const std::string& path() const { return path_; }

private:
    SqliteMatchStore(std::string path, FileLock lock, SqliteStoreOptions options);
    void enqueue(WriteItem item);
    void writer_loop();
    void checkpointer_loop();
    // Writes batch; true on success. Tells callers, counts, logs.
    bool write_batch(std::deque<WriteItem>& batch);
    void report_failure(const std::string& error, std::size_t waiting);

    std::string path_;
    FileLock lock_;
    SqliteStoreOptions options_;
    std::unique_ptr<sqlite::SqliteWriter> writer_connection_;
    std::unique_ptr<sqlite::SqliteReader> reader_;
    std::unique_ptr<sqlite::SqlitePlayerReader> player_reader_;
    std::unique_ptr<SQLite::Database> checkpoint_connection_;

    mutable std::mutex mutex_;
    std::condition_variable work_cv_; // the writer waits for work (or stop)
    std::condition_variable done_cv_; // flush waits for progress
    std::deque<WriteItem> queue_;
    std::size_t in_flight_ = 0;      // items the writer holds
    std::uint64_t queued_total_ = 0; // items accepted by enqueue
    std::uint64_t done_total_ = 0;   // items written or dropped
    bool stopping_ = false;
    std::chrono::steady_clock::time_point stop_deadline_{};
    std::string last_error_;
    bool degraded_ = false;

    std::atomic<std::uint64_t> errors_total_{0};
    std::atomic<std::uint64_t> dropped_total_{0};
    std::atomic<std::uint64_t> written_total_{0};
    std::atomic<std::uint64_t> commits_since_checkpoint_{0};

    // Writer thread only: the rate limit of failure log lines.
    std::optional<std::chrono::steady_clock::time_point> last_log_;
    std::uint64_t failures_since_log_ = 0;
    std::uint64_t failures_in_outage_ = 0;

    std::mutex checkpoint_mutex_;
    std::condition_variable checkpoint_cv_;
    bool checkpoint_stop_ = false;

    std::thread writer_;
    std::thread checkpointer_;
};

} // namespace carrom::store
