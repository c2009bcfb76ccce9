#pragma once
// Private to server/src: a room's JournalSink (room/journal_sink.hpp) on top of the MatchStore.
// Match ids are random (16 characters of [0-9a-z]); seat holders' tokens are stored as hashes
// (store::hash_token), never in clear; a confirmed append's answer comes on the store's thread
// and goes to `written`, which carrom-server's RoomActor posts to the room's strand. No Boost.

#include "carrom/room/journal_sink.hpp"
#include "carrom/server/random.hpp"
#include "store/match_store.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace carrom::server {

class StoreJournal final : public room::JournalSink {
public:
    // Called on the store's thread when a confirmed entry is written or dropped.
    using Written = std::function<void(const std::string& match_id, std::int64_t seq)>;

    // stopping: while true (the server shuts down), an abandoned match is left unfinished, so
    // that it can be recovered after a restart.
    // The identified player holding a resume token, if any (the session registry's).
    using IdentityOf = std::function<std::optional<store::PlayerKeyHash>(const std::string&)>;

    // rated: the room is rated (RoomActor::set_rated); the identified holders of a rated
    // singles game's seats as it starts (identity_of their tokens) are stored as its rated seats.
    StoreJournal(std::shared_ptr<store::MatchStore> store, RandomSource& random,
                 const std::atomic<bool>& stopping, const std::atomic<bool>& rated,
                 IdentityOf identity_of);

    void on_written(Written written) { written_ = std::move(written); }

    std::string next_match_id() override;
    void created(const proto::MatchCreated& created) override;
    void append(const std::string& match_id, std::int64_t seq, const proto::JournalEntry& entry,
                bool confirm) override;
    void seat_holder(const std::string& match_id, int seat, const std::string& token) override;
    void abandoned(const std::string& match_id) override;

private:
    std::shared_ptr<store::MatchStore> store_;
    RandomSource& random_;
    const std::atomic<bool>& stopping_;
    const std::atomic<bool>& rated_;
    IdentityOf identity_of_;
    // The rated game being started: its match id, until each of its two seats has been named.
    std::string rating_match_;
    Written written_;
};

} // namespace carrom::server
