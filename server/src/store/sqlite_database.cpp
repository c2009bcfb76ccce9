#include "store/sqlite_database.hpp"

#include "store/newer_schema_error.hpp"

#include <SQLiteCpp/Statement.h>
#include <SQLiteCpp/Transaction.h>
#include <sqlite3.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include <unistd.h>

namespace carrom::store::sqlite {
namespace {

namespace fs = std::filesystem;

constexpr int kBusyTimeoutMs = 5000;

// Migration n takes a database from schema n - 1 to schema n. Append only: a released migration
// never changes.
constexpr const char* kMigrations[] = {
    // 1: matches (the journal's head and, once known, the result), their entries, the players
    // named in them (for listing by player) and the seats' resume token hashes.
    R"sql(
CREATE TABLE matches (
    id TEXT PRIMARY KEY NOT NULL,
    room_code TEXT NOT NULL,
    rule_set TEXT NOT NULL,
    created_ms INTEGER NOT NULL,
    physics_version INTEGER NOT NULL,
    rules_version INTEGER NOT NULL,
    head TEXT NOT NULL,
    finished_ms INTEGER,
    result TEXT
);
CREATE INDEX matches_unfinished ON matches (created_ms) WHERE finished_ms IS NULL;
CREATE TABLE entries (
    match_id TEXT NOT NULL REFERENCES matches (id),
    seq INTEGER NOT NULL,
    time_ms INTEGER NOT NULL,
    type TEXT NOT NULL,
    body TEXT NOT NULL,
    PRIMARY KEY (match_id, seq)
) WITHOUT ROWID;
CREATE TABLE players (
    name TEXT NOT NULL,
    match_id TEXT NOT NULL REFERENCES matches (id),
    created_ms INTEGER NOT NULL,
    PRIMARY KEY (name, match_id)
) WITHOUT ROWID;
CREATE INDEX players_recent ON players (name, created_ms);
CREATE TABLE seat_tokens (
    match_id TEXT NOT NULL REFERENCES matches (id),
    seat INTEGER NOT NULL,
    token_sha256 BLOB NOT NULL,
    PRIMARY KEY (match_id, seat)
) WITHOUT ROWID;
)sql",
    // 2: identified players (a key's hash, never the key), their ratings per rule set, the
    // players holding the seats of a rated match, and each rating change, once per match and
    // player (docs/ratings.md).
    R"sql(
CREATE TABLE identities (
    key_sha256 BLOB PRIMARY KEY NOT NULL,
    name TEXT NOT NULL,
    name_key TEXT NOT NULL UNIQUE,
    created_ms INTEGER NOT NULL
) WITHOUT ROWID;
CREATE TABLE ratings (
    key_sha256 BLOB NOT NULL REFERENCES identities (key_sha256),
    rule_set TEXT NOT NULL,
    rating REAL NOT NULL,
    deviation REAL NOT NULL,
    volatility REAL NOT NULL,
    games INTEGER NOT NULL,
    wins INTEGER NOT NULL,
    losses INTEGER NOT NULL,
    draws INTEGER NOT NULL,
    last_game_ms INTEGER NOT NULL,
    PRIMARY KEY (key_sha256, rule_set)
) WITHOUT ROWID;
CREATE INDEX ratings_leaderboard ON ratings (rule_set, rating);
CREATE TABLE rated_seats (
    match_id TEXT NOT NULL REFERENCES matches (id),
    seat INTEGER NOT NULL,
    key_sha256 BLOB NOT NULL REFERENCES identities (key_sha256),
    PRIMARY KEY (match_id, seat)
) WITHOUT ROWID;
CREATE TABLE rating_changes (
    match_id TEXT NOT NULL REFERENCES matches (id),
    key_sha256 BLOB NOT NULL REFERENCES identities (key_sha256),
    rule_set TEXT NOT NULL,
    rating_before REAL NOT NULL,
    deviation_before REAL NOT NULL,
    rating_after REAL NOT NULL,
    deviation_after REAL NOT NULL,
    volatility_after REAL NOT NULL,
    score REAL NOT NULL,
    time_ms INTEGER NOT NULL,
    PRIMARY KEY (match_id, key_sha256)
) WITHOUT ROWID;
CREATE INDEX rating_changes_recent ON rating_changes (key_sha256, time_ms);
)sql",
};
static_assert(std::size(kMigrations) == kSchemaVersion);

StoreError make_error(std::string_view code, std::string message) {
    return StoreError{std::string(code), std::move(message)};
}

// What is already in an existing file, read without writing to it.
struct Contents {
    int user_version = 0;
    std::int32_t application_id = 0;
    int objects = 0; // rows of sqlite_schema
};

std::optional<StoreError> check_contents(const std::string& path, const Contents& c) {
    if (c.application_id != 0 && c.application_id != kApplicationId) {
        char id[16];
        std::snprintf(id, sizeof id, "0x%08x", static_cast<unsigned>(c.application_id));
        return make_error(store_code::kForeign, path +
                                                    " is a SQLite database of another "
                                                    "program (application_id " +
                                                    id + ")");
    }
    if (c.application_id == 0 && (c.user_version != 0 || c.objects != 0)) {
        return make_error(store_code::kForeign,
                          path + " is a SQLite database of another program (it has tables but "
                                 "not the carrom application_id)");
    }
    if (c.user_version > kSchemaVersion) {
        return newer_schema_error(path, c.user_version, kSchemaVersion);
    }
    return std::nullopt;
}

// Reads the header fields and checks every page (quick_check) on a read-only connection.
std::optional<StoreError> validate_existing(const std::string& path) {
    try {
        SQLite::Database db(path, SQLite::OPEN_READONLY, kBusyTimeoutMs);
        Contents c;
        c.objects = db.execAndGet("SELECT count(*) FROM sqlite_schema").getInt();
        c.user_version = db.execAndGet("PRAGMA user_version").getInt();
        c.application_id = db.execAndGet("PRAGMA application_id").getInt();
        if (auto e = check_contents(path, c)) {
            return e;
        }
        SQLite::Statement check(db, "PRAGMA quick_check(1)");
        if (check.executeStep()) {
            std::string result = check.getColumn(0).getString();
            if (result != "ok") {
                std::replace(result.begin(), result.end(), '\n', ' '); // one line
                return make_error(store_code::kCorrupt, path + " is corrupt: " + result);
            }
        }
    } catch (const SQLite::Exception& e) {
        return error_from(e, path, "reading");
    }
    return std::nullopt;
}

std::optional<StoreError> migrate(SQLite::Database& db, const std::string& path) {
    SQLite::Transaction transaction(db, SQLite::TransactionBehavior::IMMEDIATE);
    const int from = db.execAndGet("PRAGMA user_version").getInt();
    if (from > kSchemaVersion) { // written by a newer server between validation and the lock
        return newer_schema_error(path, from, kSchemaVersion);
    }
    for (int version = from + 1; version <= kSchemaVersion; ++version) {
        db.exec(kMigrations[version - 1]);
        db.exec("PRAGMA user_version = " + std::to_string(version));
    }
    db.exec("PRAGMA application_id = " + std::to_string(kApplicationId));
    transaction.commit();
    return std::nullopt;
}

} // namespace

StoreError error_from(const SQLite::Exception& e, const std::string& path, std::string_view what) {
    const std::string detail = std::string(what) + " " + path + ": " + e.what();
    switch (e.getErrorCode()) {
    case SQLITE_NOTADB:
        return make_error(store_code::kNotADatabase, path + " is not a SQLite database");
    case SQLITE_CORRUPT:
        return make_error(store_code::kCorrupt, path + " is corrupt (" + e.what() + ")");
    case SQLITE_READONLY:
        return make_error(store_code::kReadOnly, path + " is read-only (" + e.what() + ")");
    case SQLITE_CANTOPEN:
        return make_error(store_code::kCannotCreate, "cannot open " + path + " (" + e.what() + ")");
    default:
        return make_error(store_code::kIo, detail);
    }
}

SQLite::Database open_connection(const std::string& path, bool read_only) {
    SQLite::Database db(path, read_only ? SQLite::OPEN_READONLY : SQLite::OPEN_READWRITE,
                        kBusyTimeoutMs);
    // NORMAL in WAL mode: a commit writes the WAL without fsync, so it survives a crash of the
    // process; the WAL is synced at each checkpoint (docs/store.md, "Durability").
    db.exec("PRAGMA synchronous = NORMAL");
    db.exec("PRAGMA foreign_keys = ON");
    return db;
}

Prepared prepare_database(const std::string& path) {
    Prepared out;
    const auto fail = [&out](std::string_view code, std::string message) {
        out.error = make_error(code, std::move(message));
        return std::move(out);
    };
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    const bool exists = fs::exists(status);
    if (fs::is_directory(status)) {
        return fail(store_code::kIsDirectory, path + " is a directory, not a file");
    }
    if (exists && !fs::is_regular_file(status)) {
        return fail(store_code::kNotADatabase, path + " is not a regular file");
    }
    // The WAL (<path>-wal, -shm) and the lock file (<path>.lock) go next to the database.
    const fs::path parent = fs::path(path).parent_path();
    const std::string directory = parent.empty() ? "." : parent.string();
    if (exists) {
        if (::access(path.c_str(), W_OK) != 0) {
            return fail(store_code::kReadOnly, path + " is read-only");
        }
        if (::access(directory.c_str(), W_OK) != 0) {
            return fail(store_code::kReadOnly,
                        path + " is in a read-only directory (its write-ahead log and lock file "
                               "go next to it)");
        }
        if ((out.error = validate_existing(path))) {
            return out;
        }
    } else {
        if (!parent.empty() && !fs::exists(parent, ec) && !fs::create_directories(parent, ec)) {
            return fail(store_code::kCannotCreate, "cannot create " + path +
                                                       ": cannot create its directory (" +
                                                       ec.message() + ")");
        }
        if (::access(directory.c_str(), W_OK) != 0) {
            return fail(store_code::kCannotCreate,
                        "cannot create " + path + ": its directory is not writable");
        }
    }
    std::string lock_error;
    switch (out.lock.acquire(path + ".lock", lock_error)) {
    case FileLock::Result::Acquired:
        break;
    case FileLock::Result::Busy:
        return fail(store_code::kLocked, "cannot use " + path + ": " + lock_error);
    case FileLock::Result::Failed:
        return fail(store_code::kCannotCreate, "cannot use " + path + ": " + lock_error);
    }
    try {
        SQLite::Database db(path, SQLite::OPEN_READWRITE | (exists ? 0 : SQLite::OPEN_CREATE),
                            kBusyTimeoutMs);
        if (sqlite3_db_readonly(db.getHandle(), "main") == 1) {
            out.error = make_error(store_code::kReadOnly, path + " is read-only");
            return out;
        }
        const std::string mode = db.execAndGet("PRAGMA journal_mode = WAL").getString();
        if (mode != "wal") {
            out.error = make_error(store_code::kIo, "cannot switch " + path +
                                                        " to write-ahead logging (journal mode " +
                                                        mode + ")");
            return out;
        }
        out.error = migrate(db, path);
    } catch (const SQLite::Exception& e) {
        out.error = error_from(e, path, exists ? "opening" : "creating");
    }
    if (out.error) {
        out.lock = FileLock{};
    }
    return out;
}

} // namespace carrom::store::sqlite
