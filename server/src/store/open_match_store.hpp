#pragma once
// Opens the MatchStore a location names (carrom-server's --data): a PostgreSQL URL
// (postgresql://... or postgres://...) opens PostgresMatchStore; anything else is the path of an
// SQLite file (SqliteMatchStore).

#include "store/match_store.hpp"
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

OpenedStore open_match_store(const std::string& location, StoreOptions options = {});

} // namespace carrom::store
