#pragma once
// Cluster mode (docs/cluster.md): several carrom-server instances on one PostgreSQL store. The
// store's side of it, as the server sees it: the instance's lease, the matches it owns, takeovers
// of the matches of instances whose lease expired, and the news that a match was lost to another
// instance. MatchStore::cluster() gives it (null for a store without cluster mode: SQLite).
//
// Threads: the cluster's own thread renews the lease, checks ownership and claims orphaned
// matches (all the blocking database calls); the handlers run on it (on_lost also on the store's
// writer thread). Keep them short; never call the store's writes from them.

#include "store/match_store.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace carrom::store {

// What /healthz and /metrics show of the instance.
struct ClusterStatus {
    std::string instance_id;
    std::string public_url;
    bool lease_ok = false;                // the last renewal succeeded and its expiry is ahead
    std::int64_t lease_expires_ms = 0;    // Unix ms, by the database's clock, at the last renewal
    std::size_t matches_owned = 0;        // matches this instance writes (unfinished)
    std::uint64_t takeovers_total = 0;    // matches claimed from another instance (or from none)
    std::uint64_t matches_lost_total = 0; // matches another instance claimed from this one
};

// Where a room (by its code) or a seat's match (by its resume token) runs in the cluster.
struct RoomLocation {
    enum class Where {
        Nowhere,   // no such room, or no unfinished match holds the seat
        Elsewhere, // another live instance runs it: public_url
        Moving,    // its instance stopped (or handed it here) and it is not running yet: retry
    };
    Where where = Where::Nowhere;
    std::string instance_id;
    std::string public_url;
    std::string room_code;
    // locate_seat, Nowhere: the seat's latest match, finished while its room is gone (its
    // instance stopped after the last stroke was stored); empty otherwise.
    MatchId finished_match;
};

// A quick-match ticket of this instance that an instance of the cluster paired: its player goes
// to room_code at room_url.
struct QuickPairing {
    std::int64_t ticket = 0;
    std::string room_code;
    std::string room_url;
};

// What a draining instance did with a match it ran, or a room that waited for its players
// (hand_over).
struct HandedMatch {
    MatchId match; // empty: a room waiting for its players (no match yet)
    std::string room_code;
    std::string instance_id; // the instance that runs it now
    std::string public_url;
};

// A room that waits for its players, as a draining instance hands it over: its code and what
// the new instance opens it again from (JSON text the server writes and reads:
// server/src/waiting_room.hpp; the store keeps it as it is).
struct WaitingRoom {
    std::string code;
    std::string description;
};

// A rated player's wait (docs/ratings.md, "Fair pairing"; docs/cluster.md, "Quick match across
// instances"): its ticket pairs only with rated tickets whose rating is within the acceptable gap
// of the one who has waited longer (ratings::acceptable_gap, the waits by the database's clock),
// never with a ticket of the same player key.
struct RatedWait {
    double rating = 0.0; // points, in the rule set asked for
    PlayerKeyHash key_hash{};
};

// A quick-match request of one waiting player (singles).
struct QuickRequest {
    std::string rule_set;
    std::int64_t ticket = 0;        // this instance's ticket of the player, when it asks again
    std::optional<RatedWait> rated; // none: a guest, paired with guests' tickets only
};

struct QuickEnqueued {
    bool paired = false;     // true: run room_code here; the other ticket's player comes to it
    std::int64_t ticket = 0; // paired: the other instance's ticket; else this instance's new one
    std::string room_code;   // paired: the room's code (reserved for this instance)
};

struct ClusterHandlers {
    // Matches this instance has just claimed (takeover), each with its journal and seat tokens,
    // to run from where the journal ends. Called on the cluster thread.
    std::function<void(std::vector<RecoveredMatch>)> on_claimed;
    // A match of this instance that another instance claimed: write nothing more to it, stop
    // its room. Called once per match, on the cluster thread or the store's writer thread,
    // before the failed write's on_written(false) of a stroke that found it lost.
    std::function<void(const MatchId& match, const std::string& room_code)> on_lost;
    // Tickets of this instance's waiting players that another instance paired (quick match
    // across instances). Called on the directory's thread.
    std::function<void(std::vector<QuickPairing>)> on_paired;
    // Rooms waiting for their players that a draining instance handed to this one: open each
    // with its code (its members are on their way). Called on the cluster thread.
    std::function<void(std::vector<WaitingRoom>)> on_rooms_handed;
};

// The answer to a directory request, on the directory's thread (keep it short: post it on).
template <class T> using Answer = std::function<void(Loaded<T>)>;

class Cluster {
public:
    virtual ~Cluster() = default;
    // Starts the cluster thread: lease renewals, ownership checks and takeovers, every
    // renew_interval. Call once, after the matches load_unfinished gave are restored.
    virtual void start(ClusterHandlers handlers) = 0;
    // Stops the thread (idempotent). The lease is ended (expired now) when the store closes,
    // once its writes are flushed, so that the other instances claim its matches at once.
    virtual void stop() = 0;
    virtual ClusterStatus status() const = 0;

    // --- the cluster's rooms (docs/cluster.md, "Rooms across the cluster") ---------------------
    // A room code reserved for this instance in the database (unique across the cluster), taken
    // from a small pool the directory keeps filled; none when the pool is empty (the database
    // does not answer). Never blocks.
    virtual std::optional<std::string> take_room_code() = 0;
    // The room closed: its code is free for the cluster again (queued).
    virtual void release_room_code(const std::string& code) = 0;
    // Where the room with this code runs; where the unfinished match of this resume token's
    // seat runs (a room or match of this instance is never asked: the server knows its own).
    virtual void locate_room(std::string code, Answer<RoomLocation> done) = 0;
    virtual void locate_seat(TokenHash token, Answer<RoomLocation> done) = 0;

    // --- quick match across instances -----------------------------------------------------------
    // A player of this instance waits for a quick match (singles of rule_set) and no player of
    // this instance does: pairs it with a ticket of another instance (a guest: the oldest guest's;
    // a rated player: the closest acceptable rating, then the oldest) that gets a room code
    // reserved here and this instance's URL (its player comes here), or, when none is there,
    // leaves a ticket of this instance. Asked again with the player's ticket (a rated player,
    // whose acceptable gap widens as it waits), it pairs or leaves that ticket as it is; a ticket
    // paired or withdrawn meanwhile is answered unpaired (a pairing comes through on_paired).
    virtual void quick_enqueue(QuickRequest request, Answer<QuickEnqueued> done) = 0;
    // Withdraws this instance's ticket; the answer is true when it was withdrawn, false when an
    // instance paired it meanwhile (its pairing comes through on_paired).
    virtual void quick_withdraw(std::int64_t ticket, Answer<bool> done) = 0;

    // --- draining ----------------------------------------------------------------------------
    // Gives every unfinished match of this instance, and the rooms in `waiting`, to the live
    // instances (fewest matches owned first), marks them handed over, and wakes them; call once
    // the rooms stopped and the writes are flushed. Blocks (the shutdown's thread). Empty when no
    // instance is alive to take them (the matches are then claimed as orphans once the lease
    // ends; the waiting rooms are gone).
    virtual Loaded<std::vector<HandedMatch>> hand_over(std::vector<WaitingRoom> waiting) = 0;
};

} // namespace carrom::store
