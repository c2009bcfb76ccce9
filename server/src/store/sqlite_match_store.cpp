#include "store/sqlite_match_store.hpp"

#include "store/sqlite_database.hpp"
#include "store/sqlite_player_reader.hpp"
#include "store/sqlite_reader.hpp"
#include "store/sqlite_writer.hpp"

#include <SQLiteCpp/Database.h>
#include <spdlog/spdlog.h>
#include <sqlite3.h>

#include <span>

namespace carrom::store {

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
    store->start_writing(
        path, store->options_,
        [s = store.get()](std::span<WriteItem> items) {
            return s->writer_connection_->write(items, s->options_.fail_writes);
        },
        [s = store.get()] { s->commits_since_checkpoint_.fetch_add(1); });
    store->checkpointer_ = std::thread([s = store.get()] { s->checkpointer_loop(); });
    out.store = std::move(store);
    return out;
}

SqliteMatchStore::SqliteMatchStore(std::string path, FileLock lock, SqliteStoreOptions options)
    : QueuedMatchStore("sqlite"), path_(std::move(path)), lock_(std::move(lock)),
      options_(std::move(options)) {}

SqliteMatchStore::~SqliteMatchStore() {
    stop_writing();
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
            count_error();
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

} // namespace carrom::store
