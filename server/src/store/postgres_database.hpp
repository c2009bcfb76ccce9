#pragma once
// The PostgreSQL database behind PostgresMatchStore: URLs, connections, the schema and its
// migrations, the checks that open it, and the advisory lock that keeps a second single-instance
// server off it. All the SQL of the store lives in this folder (docs/store.md, "The PostgreSQL
// backend").

#include <pqxx/connection>
#include <pqxx/transaction_base>

#include "store/match_store.hpp"
#include "store/postgres_url.hpp"

#include <cstdint>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace carrom::store::postgres {

// carrom_schema.version: the schema this build writes. A database with a larger one is refused.
inline constexpr int kSchemaVersion = 5;
// carrom_schema.application: the mark of a carrom match store.
inline constexpr std::string_view kApplication = "carrom-match-store";
// The session-level advisory lock (pg_try_advisory_lock) a single-instance server holds on its
// write connection: "CRMJ".
inline constexpr std::int64_t kLockKey = 0x43524d4a;
// The class of the session-level advisory lock (pg_try_advisory_lock(kInstanceLockClass,
// hashtext(id))) a cluster instance holds on its lease connection while it runs: a second live
// process with the same instance id is refused. "CRMI".
inline constexpr int kInstanceLockClass = 0x43524d49;

// A new connection (libpq's connect_timeout 5 s unless the URL sets one). Throws
// pqxx::broken_connection (and others from pqxx) when it cannot connect.
std::unique_ptr<pqxx::connection> connect(const std::string& url);

// A store error for an exception met while doing `what` with the database (shown: its URL as
// shown_url gives it): store_cannot_connect, store_permission or store_io.
StoreError error_from(const std::exception& e, const std::string& shown, std::string_view what);

// Validates the database without writing to it (another program's tables: store_foreign; a newer
// schema: store_newer_schema), then applies the migrations it lacks in one transaction.
std::optional<StoreError> prepare_database(pqxx::connection& c, const std::string& shown);

// A text[] literal of items for a parameter ($1::text[]): each item quoted, `"` and `\` escaped.
std::string text_array(const std::vector<std::string>& items);

// Takes the one-server advisory lock on this session; false when another session holds it.
bool try_lock(pqxx::connection& c);

} // namespace carrom::store::postgres
