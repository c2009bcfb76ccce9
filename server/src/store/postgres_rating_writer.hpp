#pragma once
// The PostgreSQL store's writes of identified players and ratings (docs/ratings.md), inside the
// write transaction of PostgresWriter: a rating update commits or rolls back with the append that
// ends the match. Statements are prepared on the write connection by prepare().

#include <pqxx/connection>
#include <pqxx/transaction_base>

#include "store/write_item.hpp"

#include <cstdint>

namespace carrom::store::postgres {

class PostgresRatingWriter {
public:
    // Prepares the statements below on c (the writer's connection). Throws (pqxx).
    static void prepare(pqxx::connection& c);

    static void save_player(pqxx::transaction_base& t, const PlayerItem& item);
    static void rated_seat(pqxx::transaction_base& t, const RatedSeatItem& item);
    // The match ended with result at time_ms: when exactly seats 0 and 1 are rated and held by
    // two different players, writes both rating changes and ratings, unless this match's changes
    // are already written (then nothing: a result is applied once, guarded by the primary key
    // (match_id, key_sha256) of rating_changes).
    static void match_ended(pqxx::transaction_base& t, const MatchId& match,
                            const rules::GameResult& result, std::int64_t time_ms);
};

} // namespace carrom::store::postgres
