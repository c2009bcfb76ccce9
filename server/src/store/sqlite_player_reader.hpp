#pragma once
// The store's reads of identified players and ratings (docs/ratings.md), on a read-only
// connection of its own. Thread-safe: one mutex around the connection.

#include "store/match_store.hpp"

#include <SQLiteCpp/Database.h>

#include <mutex>
#include <string>
#include <vector>

namespace carrom::store::sqlite {

class SqlitePlayerReader {
public:
    // Opens a read-only connection to a prepared database. Throws SQLite::Exception.
    explicit SqlitePlayerReader(const std::string& path);

    Loaded<std::vector<IdentifiedPlayer>> load_players();
    Loaded<std::optional<IdentifiedPlayer>> find_player(const std::string& name_key);
    Loaded<std::vector<PlayerRating>> player_ratings(const PlayerKeyHash& player);
    Loaded<std::vector<LeaderboardRow>> leaderboard(rules::RuleSet rule_set, int limit);

private:
    template <class T, class F> Loaded<T> read(F f);

    std::mutex mutex_;
    std::string path_;
    SQLite::Database db_;
};

} // namespace carrom::store::sqlite
