#include "store/sqlite_match_store.hpp"

#include "store/sqlite_database.hpp"
#include "store/sqlite_player_reader.hpp"
#include "store/sqlite_reader.hpp"
#include "store/sqlite_writer.hpp"

#include <SQLiteCpp/Database.h>
#include <spdlog/spdlog.h>
#include <sqlite3.h>

#include <algorithm>
#include <exception>
#include <vector>

namespace carrom::store {

using Clock = std::chrono::steady_clock;

SqliteMatchStore::Opened SqliteMatchStore::open(const std::string& path,
                                                SqliteStoreOptions options) {
    Opened out;
    sqlite::Prepared prepared = sqlite::prepare_database(path);
    if (prepared.error) {
        out.error = std::move(prepared.error);
        return out;
    }
    std::unique_ptr<SqliteMatchStore> store(
        new SqliteMatchStore(path, std::move(prepared.lock), std::move(options)));
    try {
        store->writer_connection_ = std::make_unique<sqlite::SqliteWriter>(path);
        store->reader_ = std::make_unique<sqlite::SqliteReader>(path);
        store->player_reader_ = std::make_unique<sqlite::SqlitePlayerReader>(path);
        store->checkpoint_connection_ =
            std::make_unique<SQLite::Database>(sqlite::open_connection(path, false));
    } catch (const SQLite::Exception& e) {
        out.error = sqlite::error_from(e, path, "opening");
        return out;
    }
    store->writer_ = std::thread([s = store.get()] { s->writer_loop(); });
    store->checkpointer_ = std::thread([s = store.get()] { s->checkpointer_loop(); });
    out.store = std::move(store);
    return out;
}

SqliteMatchStore::SqliteMatchStore(std::string path, FileLock lock, SqliteStoreOptions options)
    : path_(std::move(path)), lock_(std::move(lock)), options_(std::move(options)) {
    options_.max_batch = std::max<std::size_t>(options_.max_batch, 1);
}

SqliteMatchStore::~SqliteMatchStore() {
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        stop_deadline_ = Clock::now() + options_.close_timeout;
    }
    work_cv_.notify_all();
    if (writer_.joinable()) {
        writer_.join();
    }
    {
        const std::lock_guard lock(checkpoint_mutex_);
        checkpoint_stop_ = true;
    }
    checkpoint_cv_.notify_all();
    if (checkpointer_.joinable()) {
        checkpointer_.join();
    }
    if (checkpoint_connection_) {
        // Everything into the database file; the WAL is emptied (removed when the last
        // connection closes).
        sqlite3_wal_checkpoint_v2(checkpoint_connection_->getHandle(), nullptr,
                                  SQLITE_CHECKPOINT_TRUNCATE, nullptr, nullptr);
    }
}

// --- writes -----------------------------------------------------------------------------------

void SqliteMatchStore::enqueue(WriteItem item) {
    {
        const std::lock_guard lock(mutex_);
        if (queue_.size() + in_flight_ < options_.max_pending && !stopping_) {
            queue_.push_back(std::move(item));
            ++queued_total_;
            work_cv_.notify_one();
            return;
        }
    }
    const std::uint64_t drops = dropped_total_.fetch_add(1, std::memory_order_relaxed) + 1;
    errors_total_.fetch_add(1, std::memory_order_relaxed);
    if (drops % 10000 == 1) { // the first, then one line per 10,000
        spdlog::error("store {}: {} items wait to be written; new items are dropped ({} so far)",
                      path_, options_.max_pending, drops);
    }
    if (item.on_written) {
        item.on_written(false);
    }
}

void SqliteMatchStore::create(proto::MatchCreated created) {
    enqueue(WriteItem{CreateItem{std::move(created)}, {}, false});
}

void SqliteMatchStore::append(const MatchId& match, std::int64_t seq, proto::JournalEntry entry,
                              OnWritten on_written) {
    enqueue(WriteItem{AppendItem{match, seq, std::move(entry)}, std::move(on_written), false});
}

void SqliteMatchStore::set_seat_token(const MatchId& match, int seat,
                                      std::optional<TokenHash> token) {
    enqueue(WriteItem{SeatTokenItem{match, seat, token}, {}, false});
}

void SqliteMatchStore::mark_finished(const MatchId& match, std::int64_t time_ms) {
    enqueue(WriteItem{FinishItem{match, time_ms}, {}, false});
}

void SqliteMatchStore::save_player(IdentifiedPlayer player) {
    enqueue(WriteItem{PlayerItem{std::move(player)}, {}, false});
}

void SqliteMatchStore::set_rated_seat(const MatchId& match, int seat, PlayerKeyHash player) {
    enqueue(WriteItem{RatedSeatItem{match, seat, player}, {}, false});
}

bool SqliteMatchStore::flush(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    const std::uint64_t target = queued_total_;
    return done_cv_.wait_for(lock, timeout, [&] { return done_total_ >= target; });
}

void SqliteMatchStore::writer_loop() {
    std::deque<WriteItem> batch; // taken from the queue; failed items stay here, in order
    auto backoff = options_.retry_initial;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            if (batch.empty()) {
                work_cv_.wait(lock, [&] { return !queue_.empty() || stopping_; });
                if (queue_.empty()) {
                    return; // stopping, and everything is written
                }
            }
            while (!queue_.empty() && batch.size() < options_.max_batch) {
                batch.push_back(std::move(queue_.front()));
                queue_.pop_front();
                ++in_flight_;
            }
        }
        if (write_batch(batch)) {
            backoff = options_.retry_initial;
            continue;
        }
        std::unique_lock lock(mutex_);
        if (stopping_ && Clock::now() >= stop_deadline_) {
            const std::size_t lost = batch.size() + queue_.size();
            spdlog::error("store {}: stopping with {} items not written ({})", path_, lost,
                          last_error_);
            dropped_total_.fetch_add(lost, std::memory_order_relaxed);
            done_total_ += lost;
            in_flight_ = 0;
            queue_.clear();
            done_cv_.notify_all();
            return;
        }
        // Sleep (new items still queue meanwhile); while stopping, not past the deadline.
        const auto wake =
            std::min(Clock::now() + backoff, stopping_ ? stop_deadline_ : Clock::time_point::max());
        work_cv_.wait_until(lock, wake, [&] { return Clock::now() >= wake; });
        backoff = std::min(backoff * 2, options_.retry_max);
    }
}

bool SqliteMatchStore::write_batch(std::deque<WriteItem>& batch) {
    std::vector<WriteItem> items(std::make_move_iterator(batch.begin()),
                                 std::make_move_iterator(batch.end()));
    batch.clear();
    std::vector<sqlite::SqliteWriter::Refusal> refused;
    std::string error;
    try {
        refused = writer_connection_->write(items, options_.fail_writes);
    } catch (const std::exception& e) {
        error = e.what();
    }
    if (!error.empty()) {
        // Nothing was written: tell each waiting caller once, keep every item for the retry.
        for (WriteItem& item : items) {
            if (!item.told && item.on_written) {
                item.on_written(false);
            }
            item.told = true;
        }
        std::size_t waiting = 0;
        {
            const std::lock_guard lock(mutex_);
            degraded_ = true;
            last_error_ = error;
            waiting = items.size() + queue_.size();
        }
        errors_total_.fetch_add(1, std::memory_order_relaxed);
        report_failure(error, waiting);
        batch.assign(std::make_move_iterator(items.begin()), std::make_move_iterator(items.end()));
        return false;
    }
    std::vector<bool> dropped(items.size(), false);
    for (const auto& r : refused) {
        spdlog::error("store {}: an item was refused and dropped: {}", path_, r.reason);
        dropped[r.index] = true;
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items[i].told && items[i].on_written) {
            items[i].on_written(!dropped[i]);
        }
    }
    const std::size_t written = items.size() - refused.size();
    written_total_.fetch_add(written, std::memory_order_relaxed);
    dropped_total_.fetch_add(refused.size(), std::memory_order_relaxed);
    errors_total_.fetch_add(refused.size(), std::memory_order_relaxed);
    commits_since_checkpoint_.fetch_add(1, std::memory_order_relaxed);
    if (failures_in_outage_ > 0) {
        spdlog::info("store {}: writing again after {} failed attempts", path_,
                     failures_in_outage_);
        failures_in_outage_ = 0;
        failures_since_log_ = 0;
        last_log_.reset();
    }
    {
        const std::lock_guard lock(mutex_);
        degraded_ = false;
        in_flight_ -= items.size();
        done_total_ += items.size();
    }
    done_cv_.notify_all();
    return true;
}

void SqliteMatchStore::report_failure(const std::string& error, std::size_t waiting) {
    ++failures_in_outage_;
    ++failures_since_log_;
    const auto now = Clock::now();
    if (last_log_ && now - *last_log_ < options_.log_interval) {
        return;
    }
    spdlog::warn("store {}: writing failed ({} failed attempts since the last report): {}; {} "
                 "items wait in memory and are retried",
                 path_, failures_since_log_, error, waiting);
    last_log_ = now;
    failures_since_log_ = 0;
}

void SqliteMatchStore::checkpointer_loop() {
    std::unique_lock lock(checkpoint_mutex_);
    while (!checkpoint_stop_) {
        checkpoint_cv_.wait_for(lock, options_.checkpoint_interval,
                                [&] { return checkpoint_stop_; });
        if (checkpoint_stop_ || commits_since_checkpoint_.exchange(0) == 0) {
            continue;
        }
        lock.unlock();
        // PASSIVE: copies what no reader needs, never waits for the writer or makes it wait.
        const int rc = sqlite3_wal_checkpoint_v2(checkpoint_connection_->getHandle(), nullptr,
                                                 SQLITE_CHECKPOINT_PASSIVE, nullptr, nullptr);
        if (rc != SQLITE_OK && rc != SQLITE_BUSY) {
            errors_total_.fetch_add(1, std::memory_order_relaxed);
            spdlog::warn("store {}: checkpoint failed: {}", path_, sqlite3_errstr(rc));
        }
        lock.lock();
    }
}

// --- reads ------------------------------------------------------------------------------------

Loaded<std::vector<RecoveredMatch>> SqliteMatchStore::load_unfinished() {
    return reader_->load_unfinished();
}

Loaded<std::optional<proto::MatchJournal>> SqliteMatchStore::journal(const MatchId& match) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->journal(match);
}

Loaded<std::vector<MatchListing>> SqliteMatchStore::recent_matches(const std::string& player,
                                                                   int limit) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->recent_matches(player, limit);
}

Loaded<std::vector<IdentifiedPlayer>> SqliteMatchStore::load_players() {
    return player_reader_->load_players();
}

Loaded<std::optional<IdentifiedPlayer>> SqliteMatchStore::find_player(const std::string& name_key) {
    if (options_.before_read) {
        options_.before_read();
    }
    return player_reader_->find_player(name_key);
}

Loaded<std::vector<PlayerRating>> SqliteMatchStore::player_ratings(const PlayerKeyHash& player) {
    if (options_.before_read) {
        options_.before_read();
    }
    return player_reader_->player_ratings(player);
}

Loaded<std::vector<LeaderboardRow>> SqliteMatchStore::leaderboard(rules::RuleSet rule_set,
                                                                  int limit) {
    if (options_.before_read) {
        options_.before_read();
    }
    return player_reader_->leaderboard(rule_set, limit);
}

StoreHealth SqliteMatchStore::health() const {
    StoreHealth h;
    h.errors_total = errors_total_.load(std::memory_order_relaxed);
    h.dropped_total = dropped_total_.load(std::memory_order_relaxed);
    h.written_total = written_total_.load(std::memory_order_relaxed);
    const std::lock_guard lock(mutex_);
    h.degraded = degraded_;
    h.pending = queue_.size() + in_flight_;
    h.last_error = last_error_;
    return h;
}

} // namespace carrom::store
