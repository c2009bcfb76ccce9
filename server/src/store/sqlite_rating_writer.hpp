#pragma once
// The store's writes of identified players and ratings (docs/ratings.md), on the write
// connection of SqliteWriter and inside its transaction: a rating update commits or rolls back
// with the append that ends the match.

#include "store/write_item.hpp"

#include <SQLiteCpp/Database.h>
#include <SQLiteCpp/Statement.h>

#include <cstdint>

namespace carrom::store::sqlite {

class SqliteRatingWriter {
public:
    // Prepares its statements on db (the writer's connection). Throws SQLite::Exception.
    explicit SqliteRatingWriter(SQLite::Database& db);

    void save_player(const PlayerItem& item);
    void rated_seat(const RatedSeatItem& item);
    // The match ended with result at time_ms: when exactly seats 0 and 1 are rated and held by
    // two different players, writes both rating changes and ratings, unless this match's changes
    // are already written (then nothing: a result is applied once).
    void match_ended(const MatchId& match, const rules::GameResult& result, std::int64_t time_ms);

private:
    SQLite::Statement upsert_player_;
    SQLite::Statement insert_rated_seat_;
    SQLite::Statement select_rated_seats_;
    SQLite::Statement select_rule_set_;
    SQLite::Statement select_rating_;
    SQLite::Statement insert_change_;
    SQLite::Statement upsert_rating_;
};

} // namespace carrom::store::sqlite
