#include "store/postgres_database.hpp"

#include "store/newer_schema_error.hpp"

#include <pqxx/pqxx>

#include <algorithm>
#include <array>
#include <set>

namespace carrom::store::postgres {
namespace {

// Migration n takes a database from schema n - 1 to schema n. Append only: a released migration
// never changes. The same logical tables as the SQLite store (sqlite_database.cpp), plus the
// ownership columns reserved for cluster mode.
constexpr const char* kMigrations[] = {
    // 1: the schema mark; matches (the journal's head and, once known, the result; owner_instance
    // and owner_epoch are reserved for cluster mode: the instance that runs the match and a
    // counter a takeover increments; a single instance leaves them NULL and 0), their entries,
    // the players named in them (for listing by player) and the seats' resume token hashes.
    R"sql(
CREATE TABLE carrom_schema (
    one boolean PRIMARY KEY DEFAULT true CHECK (one),
    application text NOT NULL,
    version integer NOT NULL
);
CREATE TABLE matches (
    id text PRIMARY KEY,
    room_code text NOT NULL,
    rule_set text NOT NULL,
    created_ms bigint NOT NULL,
    physics_version integer NOT NULL,
    rules_version integer NOT NULL,
    head text NOT NULL,
    finished_ms bigint,
    result text,
    owner_instance text,
    owner_epoch bigint NOT NULL DEFAULT 0
);
CREATE INDEX matches_unfinished ON matches (created_ms) WHERE finished_ms IS NULL;
CREATE TABLE entries (
    match_id text NOT NULL REFERENCES matches (id),
    seq bigint NOT NULL,
    time_ms bigint NOT NULL,
    type text NOT NULL,
    body text NOT NULL,
    PRIMARY KEY (match_id, seq)
);
CREATE TABLE players (
    name text NOT NULL,
    match_id text NOT NULL REFERENCES matches (id),
    created_ms bigint NOT NULL,
    PRIMARY KEY (name, match_id)
);
CREATE INDEX players_recent ON players (name, created_ms);
CREATE TABLE seat_tokens (
    match_id text NOT NULL REFERENCES matches (id),
    seat integer NOT NULL,
    token_sha256 bytea NOT NULL,
    PRIMARY KEY (match_id, seat)
);
)sql",
    // 2: identified players (a key's hash, never the key), their ratings per rule set, the
    // players holding the seats of a rated match, and each rating change, once per match and
    // player (docs/ratings.md).
    R"sql(
CREATE TABLE identities (
    key_sha256 bytea PRIMARY KEY,
    name text NOT NULL,
    name_key text NOT NULL UNIQUE,
    created_ms bigint NOT NULL
);
CREATE TABLE ratings (
    key_sha256 bytea NOT NULL REFERENCES identities (key_sha256),
    rule_set text NOT NULL,
    rating double precision NOT NULL,
    deviation double precision NOT NULL,
    volatility double precision NOT NULL,
    games integer NOT NULL,
    wins integer NOT NULL,
    losses integer NOT NULL,
    draws integer NOT NULL,
    last_game_ms bigint NOT NULL,
    PRIMARY KEY (key_sha256, rule_set)
);
CREATE INDEX ratings_leaderboard ON ratings (rule_set, rating);
CREATE TABLE rated_seats (
    match_id text NOT NULL REFERENCES matches (id),
    seat integer NOT NULL,
    key_sha256 bytea NOT NULL REFERENCES identities (key_sha256),
    PRIMARY KEY (match_id, seat)
);
CREATE TABLE rating_changes (
    match_id text NOT NULL REFERENCES matches (id),
    key_sha256 bytea NOT NULL REFERENCES identities (key_sha256),
    rule_set text NOT NULL,
    rating_before double precision NOT NULL,
    deviation_before double precision NOT NULL,
    rating_after double precision NOT NULL,
    deviation_after double precision NOT NULL,
    volatility_after double precision NOT NULL,
    score double precision NOT NULL,
    time_ms bigint NOT NULL,
    PRIMARY KEY (match_id, key_sha256)
);
CREATE INDEX rating_changes_recent ON rating_changes (key_sha256, time_ms);
)sql",
    // 3 (cluster: instances): the instances of a cluster with the address clients reach each at
    // and its lease (expiry by the database's clock), and the index by which an instance finds
    // the unfinished matches it owns.
    R"sql(
CREATE TABLE instances (
    id text PRIMARY KEY,
    public_url text NOT NULL,
    started_at timestamptz NOT NULL DEFAULT now(),
    lease_expires timestamptz NOT NULL
);
CREATE INDEX matches_owner ON matches (owner_instance) WHERE finished_ms IS NULL;
)sql",
    // 4 (cluster: one service): the room codes in use across the cluster and the instance that
    // runs each room (codes are reserved here before a room gets one: unique across the
    // cluster); the quick-match tickets of players waiting on one instance for a partner on
    // another; matches an instance handed to another when it drained; the indexes by which an
    // instance finds a seat's match and an open match's room.
    R"sql(
CREATE TABLE rooms (
    code text PRIMARY KEY,
    instance_id text NOT NULL,
    reserved_at timestamptz NOT NULL DEFAULT now()
);
CREATE INDEX rooms_instance ON rooms (instance_id);
CREATE TABLE quick_tickets (
    ticket bigserial PRIMARY KEY,
    instance_id text NOT NULL,
    rule_set text NOT NULL,
    since timestamptz NOT NULL DEFAULT now(),
    room_code text,
    room_url text
);
ALTER TABLE matches ADD COLUMN handed_over boolean NOT NULL DEFAULT false;
CREATE INDEX matches_open_room ON matches (room_code) WHERE finished_ms IS NULL;
CREATE INDEX seat_tokens_hash ON seat_tokens (token_sha256);
)sql",
    // 5 (cluster: rated quick match across instances, rooms handed over while they wait): a
    // rated player's ticket carries its rating and the hash of its player key (both NULL for a
    // guest's ticket); a room a draining instance handed over before its game began carries
    // what the new instance opens it from, until that instance has.
    R"sql(
ALTER TABLE quick_tickets ADD COLUMN rating double precision, ADD COLUMN key_sha256 bytea;
ALTER TABLE rooms ADD COLUMN waiting jsonb;
)sql",
};
static_assert(std::size(kMigrations) == kSchemaVersion);

// Every table a schema version has (what a database of ours may hold).
const std::set<std::string> kOurTables = {
    "carrom_schema", "matches",     "entries",        "players",   "seat_tokens", "identities",
    "ratings",       "rated_seats", "rating_changes", "instances", "rooms",       "quick_tickets"};

StoreError make_error(std::string_view code, std::string message) {
    std::replace(message.begin(), message.end(), '\n', ' '); // one line
    while (!message.empty() && message.back() == ' ') {
        message.pop_back();
    }
    return StoreError{std::string(code), std::move(message)};
}

bool contains(std::string_view text, std::string_view part) {
    return text.find(part) != std::string_view::npos;
}

// The first line of a libpq or server message, without its "ERROR:  " or "FATAL:  " prefix.
std::string first_line(std::string_view message) {
    message = message.substr(0, message.find('\n'));
    for (std::string_view prefix : {"ERROR:  ", "FATAL:  "}) {
        if (message.substr(0, prefix.size()) == prefix) {
            message.remove_prefix(prefix.size());
        }
    }
    return std::string(message);
}

// The version in carrom_schema, or none (no such table: a database not yet ours, or empty).
struct Contents {
    std::set<std::string> tables; // in the current schema
    std::optional<std::string> application;
    int version = 0;
};

Contents read_contents(pqxx::connection& c) {
    Contents out;
    pqxx::read_transaction t(c);
    for (const auto& row : t.exec("SELECT table_name FROM information_schema.tables "
                                  "WHERE table_schema = current_schema()")) {
        out.tables.insert(row[0].as<std::string>());
    }
    if (out.tables.count("carrom_schema") != 0) {
        const pqxx::result r = t.exec("SELECT application, version FROM carrom_schema");
        if (!r.empty()) {
            out.application = r[0][0].as<std::string>();
            out.version = r[0][1].as<int>();
        }
    }
    t.commit();
    return out;
}

std::optional<StoreError> check_contents(const Contents& c, const std::string& shown) {
    if (c.tables.empty()) {
        return std::nullopt; // a new database
    }
    if (!c.application || *c.application != kApplication) {
        std::string tables;
        for (const std::string& t : c.tables) {
            if (kOurTables.count(t) == 0) {
                tables += (tables.empty() ? "" : ", ") + t;
            }
        }
        return make_error(store_code::kForeign,
                          shown + " holds another program's tables (" +
                              (tables.empty() ? std::string("no carrom schema mark") : tables) +
                              ")");
    }
    if (c.version > kSchemaVersion) {
        return newer_schema_error(shown, c.version, kSchemaVersion);
    }
    return std::nullopt;
}

std::optional<StoreError> migrate(pqxx::connection& c, const std::string& shown) {
    pqxx::work t(c);
    // One migrator at a time (a transaction-level advisory lock, released at COMMIT).
    t.exec("SELECT pg_advisory_xact_lock(" + std::to_string(kLockKey + 1) + ")");
    int from = 0;
    if (!t.exec("SELECT 1 FROM information_schema.tables WHERE table_schema = current_schema() "
                "AND table_name = 'carrom_schema'")
             .empty()) {
        from = t.exec("SELECT version FROM carrom_schema")[0][0].as<int>();
    }
    if (from > kSchemaVersion) { // written by a newer server since the check
        return newer_schema_error(shown, from, kSchemaVersion);
    }
    for (int version = from + 1; version <= kSchemaVersion; ++version) {
        t.exec(kMigrations[version - 1]);
        t.exec("INSERT INTO carrom_schema (application, version) VALUES (" +
               t.quote(std::string(kApplication)) + ", " + std::to_string(version) +
               ") ON CONFLICT (one) DO UPDATE SET version = " + "excluded.version");
    }
    // The role must be able to do everything the store does, not only to read.
    const pqxx::result missing =
        t.exec("SELECT current_user, p, t FROM unnest(ARRAY['matches', 'entries', 'players', "
               "'seat_tokens', 'identities', 'ratings', 'rated_seats', 'rating_changes', "
               "'instances']) AS t, unnest(ARRAY['SELECT', 'INSERT', 'UPDATE', 'DELETE']) AS p "
               "WHERE NOT has_table_privilege(t, p) LIMIT 1");
    if (!missing.empty()) {
        return make_error(store_code::kPermission,
                          "cannot use " + shown + ": role " + missing[0][0].as<std::string>() +
                              " may not " + missing[0][1].as<std::string>() + " on table " +
                              missing[0][2].as<std::string>());
    }
    t.commit();
    return std::nullopt;
}

} // namespace

std::unique_ptr<pqxx::connection> connect(const std::string& url) {
    std::string with_timeout = url;
    if (!contains(url, "connect_timeout=")) {
        with_timeout += (contains(url, "?") ? "&" : "?") + std::string("connect_timeout=5");
    }
    return std::make_unique<pqxx::connection>(with_timeout);
}

StoreError error_from(const std::exception& e, const std::string& shown, std::string_view what) {
    const std::string message = first_line(e.what());
    if (dynamic_cast<const pqxx::broken_connection*>(&e) != nullptr) {
        if (contains(message, "authentication failed") || contains(message, "pg_hba.conf") ||
            contains(message, "permission denied") || contains(message, "role \"")) {
            return make_error(store_code::kPermission,
                              "cannot connect to " + shown + ": " + message);
        }
        return make_error(store_code::kCannotConnect,
                          "cannot connect to " + shown + ": " + message);
    }
    if (const auto* sql = dynamic_cast<const pqxx::sql_error*>(&e)) {
        if (sql->sqlstate() == "42501" ||
            dynamic_cast<const pqxx::insufficient_privilege*>(&e) != nullptr) {
            return make_error(store_code::kPermission,
                              std::string(what) + " " + shown + ": " + message);
        }
        if (sql->sqlstate().substr(0, 2) == "08") { // connection_exception
            return make_error(store_code::kCannotConnect,
                              std::string(what) + " " + shown + ": " + message);
        }
    }
    return make_error(store_code::kIo, std::string(what) + " " + shown + ": " + message);
}

std::optional<StoreError> prepare_database(pqxx::connection& c, const std::string& shown) {
    try {
        if (auto e = check_contents(read_contents(c), shown)) {
            return e;
        }
        return migrate(c, shown);
    } catch (const std::exception& e) {
        return error_from(e, shown, "preparing");
    }
}

bool try_lock(pqxx::connection& c) {
    pqxx::nontransaction t(c);
    return t.exec("SELECT pg_try_advisory_lock(" + std::to_string(kLockKey) + ")")[0][0].as<bool>();
}

std::string text_array(const std::vector<std::string>& items) {
    std::string out = "{";
    for (const std::string& item : items) {
        out += out.size() > 1 ? ",\"" : "\"";
        for (const char c : item) {
            if (c == '"' || c == '\\') {
                out.push_back('\\');
            }
            out.push_back(c);
        }
        out.push_back('"');
    }
    return out + "}";
}

} // namespace carrom::store::postgres
