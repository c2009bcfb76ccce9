#include "store/postgres_rating_writer.hpp"

#include "store/postgres_rating_row.hpp"
#include "store/rating_update.hpp"

#include <pqxx/pqxx>

#include <array>
#include <utility>
#include <vector>

namespace carrom::store::postgres {
namespace {

// The prepared statements of the rating writes, by name. Key hashes travel as hex text.
constexpr std::pair<const char*, const char*> kRatingStatements[] = {
    {"upsert_identity", "INSERT INTO identities (key_sha256, name, name_key, created_ms) "
                        "VALUES (decode($1, 'hex'), $2, $3, $4) ON CONFLICT (key_sha256) DO "
                        "UPDATE SET name = excluded.name, name_key = excluded.name_key"},
    {"insert_rated_seat", "INSERT INTO rated_seats (match_id, seat, key_sha256) "
                          "VALUES ($1, $2, decode($3, 'hex')) ON CONFLICT DO NOTHING"},
    {"select_rated_seats", "SELECT seat, key_sha256 FROM rated_seats WHERE match_id = $1 "
                           "ORDER BY seat LIMIT 3"},
    {"select_match_rule_set", "SELECT rule_set FROM matches WHERE id = $1"},
    {"select_rating", "SELECT rating, deviation, volatility, games, wins, losses, draws, "
                      "last_game_ms FROM ratings WHERE key_sha256 = decode($1, 'hex') "
                      "AND rule_set = $2"},
    {"insert_rating_change",
     "INSERT INTO rating_changes (match_id, key_sha256, rule_set, rating_before, "
     "deviation_before, rating_after, deviation_after, volatility_after, score, time_ms) "
     "VALUES ($1, decode($2, 'hex'), $3, $4, $5, $6, $7, $8, $9, $10) ON CONFLICT DO NOTHING"},
    {"upsert_rating", "INSERT INTO ratings (key_sha256, rule_set, rating, deviation, volatility, "
                      "games, wins, losses, draws, last_game_ms) "
                      "VALUES (decode($1, 'hex'), $2, $3, $4, $5, $6, $7, $8, $9, $10) "
                      "ON CONFLICT (key_sha256, rule_set) DO UPDATE SET "
                      "rating = excluded.rating, deviation = excluded.deviation, "
                      "volatility = excluded.volatility, games = excluded.games, "
                      "wins = excluded.wins, losses = excluded.losses, draws = excluded.draws, "
                      "last_game_ms = excluded.last_game_ms"},
};

} // namespace

void PostgresRatingWriter::prepare(pqxx::connection& c) {
    for (const auto& [name, sql] : kRatingStatements) {
        c.prepare(name, sql);
    }
}

void PostgresRatingWriter::save_player(pqxx::transaction_base& t, const PlayerItem& item) {
    t.exec_prepared("upsert_identity", to_hex(item.player.key_hash), item.player.name,
                    item.player.name_key, static_cast<std::int64_t>(item.player.created_ms));
}

void PostgresRatingWriter::rated_seat(pqxx::transaction_base& t, const RatedSeatItem& item) {
    t.exec_prepared("insert_rated_seat", item.match, item.seat, to_hex(item.player));
}

void PostgresRatingWriter::match_ended(pqxx::transaction_base& t, const MatchId& match,
                                       const rules::GameResult& result, std::int64_t time_ms) {
    std::vector<std::pair<int, PlayerKeyHash>> seats;
    for (const auto& row : t.exec_prepared("select_rated_seats", match)) {
        seats.emplace_back(row[0].as<int>(), key_hash_field(row[1]));
    }
    if (seats.size() != 2 || seats[0].first != 0 || seats[1].first != 1 ||
        seats[0].second == seats[1].second) {
        return; // not a rated match, or one player in both seats: nothing is rated
    }
    const pqxx::result rule_row = t.exec_prepared("select_match_rule_set", match);
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    if (rule_row.empty() || !rules::parse_rule_set(rule_row[0][0].as<std::string>(), rule_set)) {
        return;
    }
    const std::string rule_set_name(rules::to_string(rule_set));
    std::array<RatedSeat, 2> rated;
    for (std::size_t i = 0; i < 2; ++i) {
        rated[i].player = seats[i].second;
        const pqxx::result r =
            t.exec_prepared("select_rating", to_hex(rated[i].player), rule_set_name);
        if (!r.empty()) {
            rated[i].stored = rating_fields(r[0], 0, rule_set);
        }
    }
    for (const RatingOutcome& o : rate_singles_game(rated, rule_set, result, time_ms)) {
        const std::string player = to_hex(o.player);
        const pqxx::result inserted =
            t.exec_prepared("insert_rating_change", match, player, rule_set_name, o.before.rating,
                            o.before.deviation, o.after.rating.rating, o.after.rating.deviation,
                            o.after.rating.volatility, o.score, static_cast<std::int64_t>(time_ms));
        if (inserted.affected_rows() == 0) {
            continue; // this match's result is already in this player's rating
        }
        t.exec_prepared("upsert_rating", player, rule_set_name, o.after.rating.rating,
                        o.after.rating.deviation, o.after.rating.volatility, o.after.games,
                        o.after.wins, o.after.losses, o.after.draws,
                        static_cast<std::int64_t>(o.after.last_game_ms));
    }
}

} // namespace carrom::store::postgres
