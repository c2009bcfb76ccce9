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
    return finish_open(std::move(store), url);
}

PostgresMatchStore::Opened PostgresMatchStore::open_cluster(const std::string& url,
                                                            postgres::ClusterOptions cluster,
                                                            StoreOptions options) {
    Opened out;
    if ((out.error = postgres::check_url(url))) {
        return out;
    }
    const std::string shown = postgres::shown_url(url);
    std::unique_ptr<PostgresMatchStore> store(new PostgresMatchStore(shown, std::move(options)));
    auto ownership = std::make_shared<MatchOwnership>();
    store->writer_ =
        std::make_unique<postgres::PostgresWriter>(url, shown, cluster.instance_id, ownership);
    if ((out.error = store->writer_->open())) { // the schema first: `instances` is in it
        return out;
    }
    store->cluster_ =
        std::make_unique<postgres::PostgresCluster>(url, shown, std::move(cluster), ownership);
    if ((out.error = store->cluster_->open())) {
        return out;
    }
    return finish_open(std::move(store), url);
}

PostgresMatchStore::Opened
PostgresMatchStore::finish_open(std::unique_ptr<PostgresMatchStore> store, const std::string& url) {
    Opened out;
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

} // namespace carrom::store
