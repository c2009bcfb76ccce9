#include "store/open_match_store.hpp"

#include "store/postgres_match_store.hpp"
#include "store/postgres_url.hpp"
#include "store/sqlite_match_store.hpp"

namespace carrom::store {

OpenedStore open_match_store(const std::string& location, StoreOptions options,
                             const postgres::ClusterOptions* cluster) {
    OpenedStore out;
    if (postgres::is_postgres_url(location)) {
        out.shown = postgres::shown_url(location);
        auto opened = cluster != nullptr
                          ? PostgresMatchStore::open_cluster(location, *cluster, std::move(options))
                          : PostgresMatchStore::open(location, std::move(options));
        out.store = std::move(opened.store);
        out.error = std::move(opened.error);
    } else {
        out.shown = location;
        auto opened = SqliteMatchStore::open(location, std::move(options));
        out.store = std::move(opened.store);
        out.error = std::move(opened.error);
    }
    return out;
}

} // namespace carrom::store
