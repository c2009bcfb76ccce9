#pragma once
// The store's read connection: journals, unfinished matches and match lists, decoded and checked
// (a stored journal that does not decode, or misses an entry, is a store_bad_journal error).
// Thread-safe: one mutex around the connection.

#include "store/match_store.hpp"

#include <SQLiteCpp/Database.h>

#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace carrom::store::sqlite {

class SqliteReader {
public:
    // Opens a read-only connection to a prepared database. Throws SQLite::Exception.
    explicit SqliteReader(const std::string& path);

    Loaded<std::vector<RecoveredMatch>> load_unfinished();
    Loaded<std::optional<proto::MatchJournal>> journal(const MatchId& match);
    Loaded<std::vector<MatchListing>> recent_matches(const std::string& player, int limit);

private:
    // The journal of a match known to exist; nullopt when there is no such match.
    std::optional<proto::MatchJournal> read_journal(const MatchId& match);
    std::vector<std::optional<TokenHash>> read_tokens(const MatchId& match, int seats);

    std::mutex mutex_;
    std::string path_;
    SQLite::Database db_;
};

} // namespace carrom::store::sqlite
