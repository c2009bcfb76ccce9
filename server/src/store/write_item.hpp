#pragma once
// One unit of work queued for a store's writer: plain data, written in queue order.

#include "store/match_store.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

namespace carrom::store {

struct CreateItem {
    proto::MatchCreated created;
};
struct AppendItem {
    MatchId match;
    std::int64_t seq = 0;
    proto::JournalEntry entry;
};
struct SeatTokenItem {
    MatchId match;
    int seat = 0;
    std::optional<TokenHash> token; // none: the seat has no token any more
};
struct FinishItem {
    MatchId match;
    std::int64_t time_ms = 0;
};

struct PlayerItem {
    IdentifiedPlayer player;
};
struct RatedSeatItem {
    MatchId match;
    int seat = 0;
    PlayerKeyHash player{};
};

struct WriteItem {
    std::variant<CreateItem, AppendItem, SeatTokenItem, FinishItem, PlayerItem, RatedSeatItem> what;
    OnWritten on_written; // appends only; may be empty
};

// An item a backend left out of its transaction because it would fail every time (an append to
// a match never created, a seq written twice, text the database cannot hold).
struct WriteRefusal {
    std::size_t index = 0; // in the batch
    std::string reason;    // the database's message
    bool lost = false;     // cluster mode: the match is another instance's (docs/cluster.md)
};

} // namespace carrom::store
