#pragma once
// Where a room's match journals go (proto/journal.hpp). The Room calls its sink on the room's
// thread, in the order things happen: created() when a game starts (every seat taken, or a
// rematch), then append() with every entry of that game, numbered 0, 1, 2, ... per match.
// carrom-server's sink writes them to the match store (server/src/store_journal.hpp); tests keep
// them in memory. A room without a sink journals nothing and behaves the same otherwise.
//
// Durability: a stroke's entry is appended with confirm = true, and the room streams nothing of
// that stroke (no snapshot, event or result to anyone) until the sink answers with
// Room::journal_written(match_id, seq) on the room's thread, once the entry is written or
// dropped (a failed write is retried and the stroke waits; after RoomConfig::store_pause_after_ms
// the room tells its members the match is paused). The answer must not come from within append()
// itself. Other entries are appended with confirm = false: the room does not wait for them.

#include "carrom/proto/journal.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace carrom::room {

class JournalSink {
public:
    virtual ~JournalSink() = default;

    // A new match id (proto::is_match_id), unique among every match the sink has seen.
    virtual std::string next_match_id() = 0;
    // A game starts. created.match_id came from next_match_id().
    virtual void created(const proto::MatchCreated& created) = 0;
    // Entry seq of match match_id. confirm: answer with Room::journal_written(match_id, seq).
    virtual void append(const std::string& match_id, std::int64_t seq,
                        const proto::JournalEntry& entry, bool confirm) = 0;
    // Who holds a seat of the match now, by the holder's resume token (empty: a bot, or the seat
    // was freed). Called when the game starts (for each seat) and whenever a player takes,
    // resumes or frees a seat of the match. The token is for the sink to hash; never store it.
    virtual void seat_holder(const std::string& match_id, int seat, const std::string& token) = 0;
    // The room ends (every human gone) while the match is unfinished: it will not go on.
    virtual void abandoned(const std::string& match_id) = 0;
};

} // namespace carrom::room
