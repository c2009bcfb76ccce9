#pragma once
// Opens the MatchStore a location names (carrom-server's --data): a PostgreSQL URL
// (postgresql://... or postgres://...) opens PostgresMatchStore; anything else is the path of an
// SQLite file (SqliteMatchStore).

#include "store/match_store.hpp"
#include "store/postgres_cluster.hpp"
#include "store/store_options.hpp"

#include <memory>
#include <optional>
#include <string>

namespace carrom::store {

struct OpenedStore {
    std::unique_ptr<MatchStore> store; // set when !error
    std::optional<StoreError> error;
    std::string shown; // the location for logs (a URL's password hidden)
};

// cluster: a PostgreSQL store opens in cluster mode with these options (docs/cluster.md); an
// SQLite store ignores it.
OpenedStore open_match_store(const std::string& location, StoreOptions options = {},
                             const postgres::ClusterOptions* cluster = nullptr);

} // namespace carrom::store
