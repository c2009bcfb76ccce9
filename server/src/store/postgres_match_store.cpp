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
    return open_with(
        url, std::move(options), [&](PostgresMatchStore& store) -> std::optional<StoreError> {
            store.writer_ =
                std::make_unique<postgres::PostgresWriter>(url, store.shown_, hold_lock);
            return store.writer_->open();
        });
}

PostgresMatchStore::Opened PostgresMatchStore::open_cluster(const std::string& url,
                                                            postgres::ClusterOptions cluster,
                                                            StoreOptions options) {
    return open_with(
        url, std::move(options), [&](PostgresMatchStore& store) -> std::optional<StoreError> {
            auto ownership = std::make_shared<MatchOwnership>();
            store.writer_ = std::make_unique<postgres::PostgresWriter>(
                url, store.shown_, cluster.instance_id, ownership);
            if (auto e = store.writer_->open()) { // the schema first: `instances` is in it
                return e;
            }
            store.cluster_ = std::make_unique<postgres::PostgresCluster>(
                url, store.shown_, std::move(cluster), ownership);
            return store.cluster_->open();
        });
}

PostgresMatchStore::Opened PostgresMatchStore::open_with(
    const std::string& url, StoreOptions options,
    const std::function<std::optional<StoreError>(PostgresMatchStore&)>& open_writer) {
    Opened out;
    if ((out.error = postgres::check_url(url))) {
        return out;
    }
    std::unique_ptr<PostgresMatchStore> store(
        new PostgresMatchStore(postgres::shown_url(url), std::move(options)));
    if ((out.error = open_writer(*store))) {
        return out;
    }
    try {
        store->reader_ = std::make_unique<postgres::PostgresReader>(url, store->shown_);
    } catch (const std::exception& e) {
        out.error = postgres::error_from(e, store->shown_, "connecting to");
        return out;
    }
    store->start_writing(store->shown_, store->options_,
                         [s = store.get()](std::span<WriteItem> items) {
                             return s->writer_->write(items, s->options_.fail_writes);
                         });
    out.store = std::move(store);
    return out;
}

PostgresMatchStore::PostgresMatchStore(std::string shown, StoreOptions options)
    : QueuedMatchStore("postgresql"), shown_(std::move(shown)), options_(std::move(options)) {}

PostgresMatchStore::~PostgresMatchStore() {
    if (cluster_) {
        cluster_->stop();
    }
    stop_writing();
    if (cluster_ && writer_) {
        cluster_->end_lease(); // after the last write: the others may claim at once
    }
}

Loaded<std::vector<RecoveredMatch>> PostgresMatchStore::load_unfinished() {
    if (cluster_) {
        return cluster_->claim(true);
    }
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
