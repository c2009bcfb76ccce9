#pragma once
// The SQLite file behind SqliteMatchStore: its schema, its migrations, and the checks that open
// it. prepare_database validates an existing file without writing to it (a file that is not a
// database, a corrupt or truncated one, another program's database, one written by a newer
// carrom-server, a directory, a read-only file: a StoreError and the file untouched), then takes
// the one-server lock, switches the file to WAL and applies the migrations it lacks. All the SQL
// of the store lives in this folder.

#include "store/file_lock.hpp"
#include "store/match_store.hpp"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Exception.h>

#include <cstdint>
#include <optional>
#include <string>

namespace carrom::store::sqlite {

// PRAGMA user_version: the schema this build writes. A file with a larger one is refused.
inline constexpr int kSchemaVersion = 2;
// PRAGMA application_id: "CRMJ", the mark of a carrom match store.
inline constexpr std::int32_t kApplicationId = 0x43524d4a;

struct Prepared {
    FileLock lock; // held while the store uses the file
    std::optional<StoreError> error;
};

// Validates, locks, migrates. On error nothing was written to the file at path.
Prepared prepare_database(const std::string& path);

// Opens a connection to a prepared database with the store's settings: WAL, synchronous=NORMAL,
// foreign keys on, busy timeout. Throws SQLite::Exception.
SQLite::Database open_connection(const std::string& path, bool read_only);

// A store error for an SQLite exception met while doing `what` with the file at path.
StoreError error_from(const SQLite::Exception& e, const std::string& path, std::string_view what);

} // namespace carrom::store::sqlite
