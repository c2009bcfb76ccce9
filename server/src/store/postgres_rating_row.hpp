#pragma once
// Columns of the PostgreSQL ratings tables as the store's records: a bytea key hash, and the
// rating columns rating, deviation, volatility, games, wins, losses, draws, last_game_ms.

#include <pqxx/binarystring>
#include <pqxx/row>

#include "store/player_records.hpp"

#include <cstring>

namespace carrom::store::postgres {

// All zeros when the column is not 32 bytes (the schema never stores another length).
inline PlayerKeyHash key_hash_field(const pqxx::field& field) {
    const pqxx::binarystring blob(field);
    PlayerKeyHash hash{};
    if (blob.size() == hash.size()) {
        std::memcpy(hash.data(), blob.data(), hash.size());
    }
    return hash;
}

// The eight rating columns from column `first` on.
inline PlayerRating rating_fields(const pqxx::row& row, int first, rules::RuleSet rule_set) {
    PlayerRating r;
    r.rule_set = rule_set;
    r.rating = ratings::Rating{row[first].as<double>(), row[first + 1].as<double>(),
                               row[first + 2].as<double>()};
    r.games = row[first + 3].as<int>();
    r.wins = row[first + 4].as<int>();
    r.losses = row[first + 5].as<int>();
    r.draws = row[first + 6].as<int>();
    r.last_game_ms = row[first + 7].as<std::int64_t>();
    return r;
}

} // namespace carrom::store::postgres
