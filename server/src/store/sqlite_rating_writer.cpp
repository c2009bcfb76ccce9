#include "store/sqlite_rating_writer.hpp"

#include "store/rating_update.hpp"
#include "store/sqlite_key_hash.hpp"

#include <array>
#include <vector>

namespace carrom::store::sqlite {
namespace {

// Resets a statement after use, even when a step throws.
struct StatementReset {
    SQLite::Statement& statement;
    ~StatementReset() {
        statement.tryReset();
        try {
            statement.clearBindings();
        } catch (...) {
        }
    }
};

} // namespace

SqliteRatingWriter::SqliteRatingWriter(SQLite::Database& db)
    : upsert_player_(db, "INSERT INTO identities (key_sha256, name, name_key, created_ms) "
                         "VALUES (?, ?, ?, ?) ON CONFLICT (key_sha256) DO UPDATE SET "
                         "name = excluded.name, name_key = excluded.name_key"),
      insert_rated_seat_(db, "INSERT OR IGNORE INTO rated_seats (match_id, seat, key_sha256) "
                             "VALUES (?, ?, ?)"),
      select_rated_seats_(db, "SELECT seat, key_sha256 FROM rated_seats WHERE match_id = ? "
                              "ORDER BY seat"),
      select_rule_set_(db, "SELECT rule_set FROM matches WHERE id = ?"),
      select_rating_(db, "SELECT rating, deviation, volatility, games, wins, losses, draws, "
                         "last_game_ms FROM ratings WHERE key_sha256 = ? AND rule_set = ?"),
      insert_change_(db, "INSERT OR IGNORE INTO rating_changes (match_id, key_sha256, rule_set, "
                         "rating_before, deviation_before, rating_after, deviation_after, "
                         "volatility_after, score, time_ms) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
      upsert_rating_(db, "INSERT INTO ratings (key_sha256, rule_set, rating, deviation, "
                         "volatility, games, wins, losses, draws, last_game_ms) "
                         "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?) "
                         "ON CONFLICT (key_sha256, rule_set) DO UPDATE SET "
                         "rating = excluded.rating, deviation = excluded.deviation, "
                         "volatility = excluded.volatility, games = excluded.games, "
                         "wins = excluded.wins, losses = excluded.losses, "
                         "draws = excluded.draws, last_game_ms = excluded.last_game_ms") {}

void SqliteRatingWriter::save_player(const PlayerItem& item) {
    const StatementReset reset{upsert_player_};
    bind_key_hash(upsert_player_, 1, item.player.key_hash);
    upsert_player_.bind(2, item.player.name);
    upsert_player_.bind(3, item.player.name_key);
    upsert_player_.bind(4, static_cast<std::int64_t>(item.player.created_ms));
    upsert_player_.exec();
}

void SqliteRatingWriter::rated_seat(const RatedSeatItem& item) {
    const StatementReset reset{insert_rated_seat_};
    insert_rated_seat_.bind(1, item.match);
    insert_rated_seat_.bind(2, item.seat);
    bind_key_hash(insert_rated_seat_, 3, item.player);
    insert_rated_seat_.exec();
}

void SqliteRatingWriter::match_ended(const MatchId& match, const rules::GameResult& result,
                                     std::int64_t time_ms) {
    std::vector<std::pair<int, PlayerKeyHash>> seats;
    {
        const StatementReset reset{select_rated_seats_};
        select_rated_seats_.bind(1, match);
        while (select_rated_seats_.executeStep() && seats.size() <= 2) {
            seats.emplace_back(select_rated_seats_.getColumn(0).getInt(),
                               key_hash_column(select_rated_seats_.getColumn(1)));
        }
    }
    if (seats.size() != 2 || seats[0].first != 0 || seats[1].first != 1 ||
        seats[0].second == seats[1].second) {
        return; // not a rated match, or one player in both seats: nothing is rated
    }
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    {
        const StatementReset reset{select_rule_set_};
        select_rule_set_.bind(1, match);
        if (!select_rule_set_.executeStep() ||
            !rules::parse_rule_set(select_rule_set_.getColumn(0).getString(), rule_set)) {
            return;
        }
    }
    const std::string rule_set_name(rules::to_string(rule_set));
    std::array<RatedSeat, 2> rated;
    for (std::size_t i = 0; i < 2; ++i) {
        rated[i].player = seats[i].second;
        const StatementReset reset{select_rating_};
        bind_key_hash(select_rating_, 1, rated[i].player);
        select_rating_.bind(2, rule_set_name);
        if (select_rating_.executeStep()) {
            PlayerRating stored;
            stored.rule_set = rule_set;
            stored.rating = ratings::Rating{select_rating_.getColumn(0).getDouble(),
                                            select_rating_.getColumn(1).getDouble(),
                                            select_rating_.getColumn(2).getDouble()};
            stored.games = select_rating_.getColumn(3).getInt();
            stored.wins = select_rating_.getColumn(4).getInt();
            stored.losses = select_rating_.getColumn(5).getInt();
            stored.draws = select_rating_.getColumn(6).getInt();
            stored.last_game_ms = select_rating_.getColumn(7).getInt64();
            rated[i].stored = stored;
        }
    }
    for (const RatingOutcome& o : rate_singles_game(rated, rule_set, result, time_ms)) {
        {
            const StatementReset reset{insert_change_};
            insert_change_.bind(1, match);
            bind_key_hash(insert_change_, 2, o.player);
            insert_change_.bind(3, rule_set_name);
            insert_change_.bind(4, o.before.rating);
            insert_change_.bind(5, o.before.deviation);
            insert_change_.bind(6, o.after.rating.rating);
            insert_change_.bind(7, o.after.rating.deviation);
            insert_change_.bind(8, o.after.rating.volatility);
            insert_change_.bind(9, o.score);
            insert_change_.bind(10, static_cast<std::int64_t>(time_ms));
            if (insert_change_.exec() == 0) {
                continue; // this match's result is already in this player's rating
            }
        }
        const StatementReset reset{upsert_rating_};
        bind_key_hash(upsert_rating_, 1, o.player);
        upsert_rating_.bind(2, rule_set_name);
        upsert_rating_.bind(3, o.after.rating.rating);
        upsert_rating_.bind(4, o.after.rating.deviation);
        upsert_rating_.bind(5, o.after.rating.volatility);
        upsert_rating_.bind(6, o.after.games);
        upsert_rating_.bind(7, o.after.wins);
        upsert_rating_.bind(8, o.after.losses);
        upsert_rating_.bind(9, o.after.draws);
        upsert_rating_.bind(10, static_cast<std::int64_t>(o.after.last_game_ms));
        upsert_rating_.exec();
    }
}

} // namespace carrom::store::sqlite
