#include "store/sqlite_player_reader.hpp"

#include "store/sqlite_database.hpp"
#include "store/sqlite_key_hash.hpp"

#include <SQLiteCpp/Statement.h>

#include <algorithm>

namespace carrom::store::sqlite {
namespace {

// The rating columns rating, deviation, volatility, games, wins, losses, draws, last_game_ms
// from column `first` on.
PlayerRating rating_columns(SQLite::Statement& row, int first, rules::RuleSet rule_set) {
    PlayerRating r;
    r.rule_set = rule_set;
    r.rating =
        ratings::Rating{row.getColumn(first).getDouble(), row.getColumn(first + 1).getDouble(),
                        row.getColumn(first + 2).getDouble()};
    r.games = row.getColumn(first + 3).getInt();
    r.wins = row.getColumn(first + 4).getInt();
    r.losses = row.getColumn(first + 5).getInt();
    r.draws = row.getColumn(first + 6).getInt();
    r.last_game_ms = row.getColumn(first + 7).getInt64();
    return r;
}

// The columns key_sha256, name, name_key, created_ms.
IdentifiedPlayer player_columns(SQLite::Statement& row) {
    return IdentifiedPlayer{key_hash_column(row.getColumn(0)), row.getColumn(1).getString(),
                            row.getColumn(2).getString(), row.getColumn(3).getInt64()};
}

} // namespace

SqlitePlayerReader::SqlitePlayerReader(const std::string& path)
    : path_(path), db_(open_connection(path, true)) {}

// Runs f in one read transaction and maps a failure to a StoreError.
template <class T, class F> Loaded<T> SqlitePlayerReader::read(F f) {
    const std::lock_guard lock(mutex_);
    Loaded<T> out;
    try {
        db_.exec("BEGIN");
        try {
            out.value = f();
        } catch (...) {
            db_.exec("ROLLBACK");
            throw;
        }
        db_.exec("COMMIT");
    } catch (const SQLite::Exception& e) {
        out.error = error_from(e, path_, "reading");
    }
    return out;
}

Loaded<std::vector<IdentifiedPlayer>> SqlitePlayerReader::load_players() {
    return read<std::vector<IdentifiedPlayer>>([this] {
        std::vector<IdentifiedPlayer> players;
        SQLite::Statement row(db_, "SELECT key_sha256, name, name_key, created_ms FROM identities");
        while (row.executeStep()) {
            players.push_back(
                IdentifiedPlayer{key_hash_column(row.getColumn(0)), row.getColumn(1).getString(),
                                 row.getColumn(2).getString(), row.getColumn(3).getInt64()});
        }
        return players;
    });
}

Loaded<std::optional<IdentifiedPlayer>>
SqlitePlayerReader::find_player(const std::string& name_key) {
    return read<std::optional<IdentifiedPlayer>>([this, &name_key] {
        std::optional<IdentifiedPlayer> out;
        SQLite::Statement row(db_, "SELECT key_sha256, name, name_key, created_ms FROM identities "
                                   "WHERE name_key = ?");
        row.bind(1, name_key);
        if (row.executeStep()) {
            out = player_columns(row);
        }
        return out;
    });
}

Loaded<std::vector<PlayerRating>> SqlitePlayerReader::player_ratings(const PlayerKeyHash& player) {
    return read<std::vector<PlayerRating>>([this, &player] {
        std::vector<PlayerRating> out;
        SQLite::Statement row(db_, "SELECT rule_set, rating, deviation, volatility, games, wins, "
                                   "losses, draws, last_game_ms FROM ratings "
                                   "WHERE key_sha256 = ? ORDER BY rule_set");
        bind_key_hash(row, 1, player);
        while (row.executeStep()) {
            rules::RuleSet rule_set = rules::RuleSet::Icf;
            if (rules::parse_rule_set(row.getColumn(0).getString(), rule_set)) {
                out.push_back(rating_columns(row, 1, rule_set));
            }
        }
        return out;
    });
}

Loaded<std::vector<LeaderboardRow>> SqlitePlayerReader::leaderboard(rules::RuleSet rule_set,
                                                                    int limit) {
    return read<std::vector<LeaderboardRow>>([this, rule_set, limit] {
        std::vector<LeaderboardRow> out;
        SQLite::Statement row(
            db_, "SELECT i.name, r.rating, r.deviation, r.volatility, r.games, r.wins, r.losses, "
                 "r.draws, r.last_game_ms FROM ratings r JOIN identities i USING (key_sha256) "
                 "WHERE r.rule_set = ? AND r.deviation < ? "
                 "ORDER BY r.rating DESC, r.games DESC, i.name_key LIMIT ?");
        row.bind(1, std::string(rules::to_string(rule_set)));
        row.bind(2, ratings::kProvisionalDeviation);
        row.bind(3, std::clamp(limit, 1, kMaxLeaderboardRows));
        while (row.executeStep()) {
            out.push_back(
                LeaderboardRow{row.getColumn(0).getString(), rating_columns(row, 1, rule_set)});
        }
        return out;
    });
}

} // namespace carrom::store::sqlite
