#pragma once
// A player's key hash as a SQLite BLOB column (32 bytes).

#include "store/player_records.hpp"

#include <SQLiteCpp/Column.h>
#include <SQLiteCpp/Statement.h>

#include <algorithm>

namespace carrom::store::sqlite {

inline void bind_key_hash(SQLite::Statement& statement, int index, const PlayerKeyHash& hash) {
    statement.bind(index, hash.data(), static_cast<int>(hash.size()));
}

// All zeros when the column is not 32 bytes (the schema never stores another length).
inline PlayerKeyHash key_hash_column(const SQLite::Column& column) {
    PlayerKeyHash hash{};
    if (column.getBytes() == static_cast<int>(hash.size())) {
        const auto* bytes = static_cast<const std::uint8_t*>(column.getBlob());
        std::copy(bytes, bytes + hash.size(), hash.begin());
    }
    return hash;
}

} // namespace carrom::store::sqlite
