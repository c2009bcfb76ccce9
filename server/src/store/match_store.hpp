#pragma once
// Where match journals live (proto/journal.hpp): the one storage interface the server uses.
// Backends implement it: the embedded default, SQLite (sqlite_match_store.hpp), and PostgreSQL
// (postgres_match_store.hpp); open_match_store.hpp picks one by the location's form.
//
// Writes never block the caller: create, append, set_seat_token and mark_finished queue their
// work and return at once; the backend writes it in the order it was queued, on its own thread
// (batched into transactions). An append can say when its entry is written, so that a
// room broadcasts a stroke only once the stroke would survive a crash of the process. When
// writing fails (disk full, I/O error), the backend keeps what it could not write in memory,
// retries, counts the errors and reports itself degraded (health()); the caller carries on.
//
// Reads (load_unfinished, journal, recent_matches) may block and may be called from any thread;
// they see what has been written, not what is still queued.

#include "carrom/proto/journal.hpp"
#include "store/player_records.hpp"
#include "store/sha256.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace carrom::store {

using MatchId = std::string; // proto::is_match_id

// sha256 of a resume token (sha256.hpp): a seat's token is stored as this, never in clear.
using TokenHash = Sha256Digest;
TokenHash hash_token(std::string_view token);

// A problem opening or reading the store: a stable code and one line naming the path.
struct StoreError {
    std::string code;    // one of the store_code constants
    std::string message; // one line, e.g. "carrom-data/carrom.db is not a SQLite database"
};

namespace store_code {
inline constexpr std::string_view kNotADatabase = "store_not_a_database"; // any other file
inline constexpr std::string_view kCorrupt = "store_corrupt";             // damaged or truncated
inline constexpr std::string_view kForeign = "store_foreign";          // another program's database
inline constexpr std::string_view kNewerSchema = "store_newer_schema"; // a newer carrom-server's
inline constexpr std::string_view kIsDirectory = "store_is_directory";
inline constexpr std::string_view kReadOnly = "store_read_only";         // the file is not writable
inline constexpr std::string_view kCannotCreate = "store_cannot_create"; // nor its directory
inline constexpr std::string_view kLocked = "store_locked";              // another server uses it
inline constexpr std::string_view kIo = "store_io";                      // any other I/O failure
inline constexpr std::string_view kCannotConnect = "store_cannot_connect"; // PostgreSQL: no
                                                                           // server, no database
inline constexpr std::string_view kPermission = "store_permission"; // PostgreSQL: the role may not
                                                                    // log in, read or create
inline constexpr std::string_view kBadUrl = "store_bad_url"; // a PostgreSQL URL libpq refuses
inline constexpr std::string_view kBadJournal = "store_bad_journal"; // a stored journal that
                                                                     // does not decode
} // namespace store_code

// A value or the error that prevented reading it.
template <class T> struct Loaded {
    T value{};
    std::optional<StoreError> error;
    bool ok() const { return !error.has_value(); }
};

// An unfinished match, for recovery after a restart.
struct RecoveredMatch {
    MatchId id;
    std::optional<proto::MatchJournal> journal;        // empty when error is set
    std::optional<StoreError> error;                   // this match's journal could not be read
    std::vector<std::optional<TokenHash>> seat_tokens; // by seat; empty optional: none stored
    bool rated = false; // its game started with rated seats (set_rated_seat)
};

// One line of a player's match list.
struct MatchListing {
    MatchId id;
    std::string room_code;
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    std::vector<std::string> players; // seat names as the game started
    std::vector<int> teams;           // per seat: its team (singles: the seat; doubles: seat % 2)
    std::int64_t created_ms = 0;      // Unix time
    std::optional<std::int64_t> finished_ms;
    std::optional<rules::GameResult> result; // set when the game ended by the rules
    std::vector<int> scores;                 // per team, with the result
};

struct StoreHealth {
    bool degraded = false;           // the last write attempt failed; entries wait in memory
    std::uint64_t errors_total = 0;  // failed write attempts (carrom_store_errors_total)
    std::uint64_t dropped_total = 0; // items given up (queue over its bound, or refused by the
                                     // backend as invalid); each also counts as an error
    std::uint64_t written_total = 0; // items written
    std::size_t pending = 0;         // items queued or being written
    std::string last_error;          // the last write error's message ("" if none yet)
    std::string backend;             // "sqlite" or "postgresql"
};

// Called once per append when the entry's fate is known, on the backend's thread (or within
// append itself when the entry is dropped at once, the store being full): written=true
// once it is written (SQLite: committed to the WAL, so it survives a crash of the process;
// PostgreSQL: its COMMIT returned);
// written=false when it was dropped (the store full, the entry refused as invalid, or its match
// lost to another instance). A failed attempt tells nothing: the backend retries the entry until
// it is written, and the caller waits for it as long as the database does not answer. Keep it
// short; never call the store from it.
using OnWritten = std::function<void(bool written)>;

class Cluster;

class MatchStore {
public:
    virtual ~MatchStore() = default;
    MatchStore() = default;
    MatchStore(const MatchStore&) = delete;
    MatchStore& operator=(const MatchStore&) = delete;

    // --- writes: queued, never blocking -----------------------------------------------------

    // A new match; its entries follow with seq 0, 1, 2, ...
    virtual void create(proto::MatchCreated created) = 0;
    // Entry number seq (0-based, consecutive) of a created match. Entries whose outcome ends the
    // game (game_end) also mark the match finished with its result.
    virtual void append(const MatchId& match, std::int64_t seq, proto::JournalEntry entry,
                        OnWritten on_written = {}) = 0;
    // The hash of the resume token that holds a seat, or none (the seat was freed).
    virtual void set_seat_token(const MatchId& match, int seat, std::optional<TokenHash> token) = 0;
    // The match will not go on (abandoned, or not resumable); idempotent. A match whose game
    // ended by the rules is marked finished by its last append.
    virtual void mark_finished(const MatchId& match, std::int64_t time_ms) = 0;
    // An identified player, new or renamed (keyed by its key hash; name_key unique).
    virtual void save_player(IdentifiedPlayer player) = 0;
    // The identified player holding a seat of a rated match as the game starts (queue it after
    // create, before the game's appends). The append whose outcome ends a match with two rated
    // seats held by two different players writes both players' rating updates in the same
    // transaction as the result, once per match and player (docs/ratings.md).
    virtual void set_rated_seat(const MatchId& match, int seat, PlayerKeyHash player) = 0;

    // Waits until everything queued before the call is done: written, or dropped (counted in
    // health()). False when the timeout came first (writes still failing, or slow).
    virtual bool flush(std::chrono::milliseconds timeout) = 0;

    // --- reads: may block ---------------------------------------------------------------------

    // Every match not finished, oldest first, with its journal and seat tokens.
    virtual Loaded<std::vector<RecoveredMatch>> load_unfinished() = 0;
    // A match's journal; an empty optional if there is no such match.
    virtual Loaded<std::optional<proto::MatchJournal>> journal(const MatchId& match) = 0;
    // The player's most recent matches (by creation time, newest first), at most limit (1..100).
    virtual Loaded<std::vector<MatchListing>> recent_matches(const std::string& player,
                                                             int limit) = 0;

    // Every identified player (the server keeps the names in memory; docs/ratings.md).
    virtual Loaded<std::vector<IdentifiedPlayer>> load_players() = 0;
    // The identified player whose name has this comparison key, if any.
    virtual Loaded<std::optional<IdentifiedPlayer>> find_player(const std::string& name_key) = 0;
    // The player's ratings, one per rule set played rated; empty if none.
    virtual Loaded<std::vector<PlayerRating>> player_ratings(const PlayerKeyHash& player) = 0;
    // Established ratings (deviation below ratings::kProvisionalDeviation) of a rule set, best
    // first (ties: more games, then the name), at most limit (1..100).
    virtual Loaded<std::vector<LeaderboardRow>> leaderboard(rules::RuleSet rule_set, int limit) = 0;

    virtual StoreHealth health() const = 0;

    // Cluster mode (cluster.hpp): the instance's lease, takeovers and lost matches; null for a
    // store without it (SQLite, and a PostgreSQL store opened for one server).
    virtual Cluster* cluster() { return nullptr; }
};

} // namespace carrom::store
