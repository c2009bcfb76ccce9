#include "store/postgres_match_store.hpp"

#include "store/postgres_database.hpp"
#include "store/postgres_reader.hpp"
#include "store/postgres_url.hpp"
#include "store/postgres_writer.hpp"

#include <exception>
#include <span>

namespace carrom::store {

PostgresMatchStore::Opened PostgresMatchStore::open(const std::string& url, StoreOptions options,
                                                    bool hold_lock) {
    Opened out;
    if ((out.error = postgres::check_url(url))) {
        return out;
    }
    const std::string shown = postgres::shown_url(url);
    std::unique_ptr<PostgresMatchStore> store(new PostgresMatchStore(shown, std::move(options)));
    store->writer_ = std::make_unique<postgres::PostgresWriter>(url, shown, hold_lock);
    if ((out.error = store->writer_->open())) {
        return out;
    }
    try {
        store->reader_ = std::make_unique<postgres::PostgresReader>(url, shown);
    } catch (const std::exception& e) {
        out.error = postgres::error_from(e, shown, "connecting to");
        return out;
    }
    store->start_writing(shown, store->options_, [s = store.get()](std::span<WriteItem> items) {
        return s->writer_->write(items, s->options_.fail_writes);
    });
    out.store = std::move(store);
    return out;
}

PostgresMatchStore::PostgresMatchStore(std::string shown, StoreOptions options)
    : QueuedMatchStore("postgresql"), shown_(std::move(shown)), options_(std::move(options)) {}

PostgresMatchStore::~PostgresMatchStore() {
    stop_writing();
}

Loaded<std::vector<RecoveredMatch>> PostgresMatchStore::load_unfinished() {
    return reader_->load_unfinished();
}

Loaded<std::optional<proto::MatchJournal>> PostgresMatchStore::journal(const MatchId& match) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->journal(match);
}

Loaded<std::vector<MatchListing>> PostgresMatchStore::recent_matches(const std::string& player,
                                                                     int limit) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->recent_matches(player, limit);
}

Loaded<std::vector<IdentifiedPlayer>> PostgresMatchStore::load_players() {
    return reader_->load_players();
}

Loaded<std::optional<IdentifiedPlayer>>
PostgresMatchStore::find_player(const std::string& name_key) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->find_player(name_key);
}

Loaded<std::vector<PlayerRating>> PostgresMatchStore::player_ratings(const PlayerKeyHash& player) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->player_ratings(player);
}

Loaded<std::vector<LeaderboardRow>> PostgresMatchStore::leaderboard(rules::RuleSet rule_set,
                                                                    int limit) {
    if (options_.before_read) {
        options_.before_read();
    }
    return reader_->leaderboard(rule_set, limit);
}

} // namespace carrom::store
