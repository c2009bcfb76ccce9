#pragma once
// One room: its seats (2, or 4 for doubles: rules.seat_count), spectators, the match and the shot
// being streamed. Plain single-threaded
// logic (carrom-server calls it only on the room's strand; the client's offline demo on its UI
// thread); time comes from the injected clock. The room answers its members through Peer::send:
// broadcasts are encoded once and shared.
//
// Time-driven work happens in tick(): snapshots while a shot streams, the shot clock, grace
// periods, the pause of a stroke whose journal entry waits. next_wake_ms() says when tick() is
// next needed (nothing while the board is at rest and no deadline is pending).

#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/room/bot_seat.hpp"
#include "carrom/room/clock.hpp"
#include "carrom/room/emote_limiter.hpp"
#include "carrom/room/journal_sink.hpp"
#include "carrom/room/peer.hpp"
#include "carrom/room/room_counters.hpp"
#include "carrom/room/room_observer.hpp"
#include "carrom/room/shot_stream.hpp"
#include "carrom/rules/match.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carrom::room {

// How long a stroke waits for its journal entry to be written before the room tells its members
// the match is paused (RoomConfig::store_pause_after_ms), in ms.
inline constexpr std::int64_t kStorePauseAfterMs = 1000;

struct RoomConfig {
    proto::RuleSet rule_set = proto::RuleSet::Icf;
    rules::RulesConfig rules{};
    PhysicsConfig physics{};
    // Deltas while a shot plays: one at every change of motion (contact, stop, pocketing) when
    // contact_snapshots, plus snapshot_hz per second in between.
    double snapshot_hz = 10.0;
    bool contact_snapshots = true;
    double grace_s = 60.0;
    double time_scale = 1.0;    // match seconds per wall second while a shot plays
    std::string server_version; // journaled in MatchCreated.versions.server
    // room_state's aim_assist: clients may draw the first-contact aim guide. Off in a rated
    // room (docs/ratings.md), on in every other.
    bool aim_assist = true;
    // A stroke whose journal entry waits longer than this (ms) for the sink's answer pauses the
    // match: every member gets the event `paused` (reason "store") once, and `resumed` when the
    // entry is written, before the stroke streams (docs/cluster.md, "The database down").
    std::int64_t store_pause_after_ms = kStorePauseAfterMs;
};

// How a restored room's seat is held again (Room::restore), by seat index.
struct RestoredSeat {
    std::int64_t player_id = -1;   // a human seat: the player id that resumes it (Room::resume)
    std::shared_ptr<BotBrain> bot; // a bot seat: its brain
};

// A journal's seats after its membership entries (joins and leaves), by seat index: name and bot
// flag (an empty name: the seat was freed).
std::vector<proto::JournalSeat> journal_seats(const proto::MatchJournal& journal);

// Rules config for a create_room request: the rule set's defaults, the server's shot clock,
// then the request's options.
rules::RulesConfig make_rules_config(proto::RuleSet rule_set, const proto::RoomOptions& options,
                                     double default_shot_clock_s);

class Room {
public:
    // observer: told about members and game ends (may be null). journal: gets the match
    // journals (journal_sink.hpp; may be null: nothing is journaled). Both outlive the room.
    Room(std::string code, RoomConfig config, const Clock& clock, RoomCounters& counters,
         RoomObserver* observer = nullptr, JournalSink* journal = nullptr);
    ~Room();
    Room(const Room&) = delete;
    Room& operator=(const Room&) = delete;

    const std::string& code() const { return code_; }
    proto::RuleSet rule_set() const { return config_.rule_set; }
    int seat_count() const { return static_cast<int>(seats_.size()); }
    const RoomConfig& config() const { return config_; }

    // Restores an unfinished match from its journal into this new room (no member, no game):
    // the state after the journal's last entry (proto::replay), the seats (humans dropped, their
    // grace period starting now, each journaled as a drop unless its last entry already was one;
    // bots thinking again), the shot clock restarted for the player to move. The room goes on
    // journaling the same match id from seq journal.entries.size(). The room's config must have
    // the journal's rule set and physics. Returns why the match cannot be resumed (one sentence;
    // the room is left untouched): a journal that does not replay clean, a game already over,
    // seats that do not match the journal's.
    std::optional<std::string> restore(const proto::MatchJournal& journal,
                                       std::vector<RestoredSeat> seats);

    // Membership. On success the peer gets room_state and a keyframe; everyone else a
    // room_state. Errors: room_full, already_in_room.
    std::optional<proto::Error> join(std::shared_ptr<Peer> peer, proto::Role role);
    // Reclaims the seat held by peer->player_id() (dropped or still connected elsewhere: the
    // old connection is closed with "replaced"). Error bad_token if the player holds no seat.
    std::optional<proto::Error> resume(std::shared_ptr<Peer> peer);
    // Seats a bot in the first free seat, or in `seat` when it is >= 0. Errors: room_full (no
    // free seat, or `seat` is taken), bad_field (`seat` is not a seat of this room).
    std::optional<proto::Error> seat_bot(std::string name, std::shared_ptr<BotBrain> brain,
                                         int seat = -1);
    // Members are identified by their connection (a replaced connection has no say any more).
    // Leaves for good: a seated player in a running game forfeits.
    void leave(const Peer& peer);
    // The connection dropped: a seat is kept for the grace period, a spectator is removed.
    void disconnected(const Peer& peer);

    // Game input (errors go to the sender).
    void aim(Peer& peer, const proto::Aim& aim);
    void shoot(Peer& peer, const proto::Shoot& shoot);
    void rematch(Peer& peer);
    // A quick reaction from a seated player once the game has started (also after game over),
    // broadcast to every member as an "emote" event, the sender included. Not journaled: it is
    // no part of the match. Errors: spectator, not_in_room, wrong_phase, emote_too_fast (the
    // seat's EmoteLimiter; the emote is dropped, the match goes on untouched).
    void emote(Peer& peer, const proto::EmoteMessage& emote);

    // Bots: the bot's turn, once per turn; then its shot (see BotShotOutcome).
    std::optional<BotTurn> take_bot_turn();
    BotShotOutcome bot_shoot(int seat, int turn, const Shot& shot);

    void tick();
    std::optional<std::int64_t> next_wake_ms() const;

    // The journal sink's answer to a confirmed append: a stroke waiting for it starts streaming.
    // Answers for another match or entry are ignored.
    void journal_written(const std::string& match_id, std::int64_t seq);
    // The current game's match id in the journal ("" without a sink or before the first game).
    const std::string& match_id() const { return match_id_; }
    // Closes every member's connection (seat holders and spectators) with close_code and reason,
    // as the server does for a match another instance took over; the room's state stays.
    void close_connections(int close_code, const std::string& reason);

    // No human holds a seat (connected or within grace) and no spectator watches.
    bool abandoned() const;
    // No game has begun yet, no bot holds a seat, and the room is not abandoned: a room that
    // waits for its players (a draining server hands it over with its code).
    bool waiting_for_players() const;
    bool is_member(const Peer& peer) const;
    int seat_of(const Peer& peer) const;              // -1 if none (a spectator or not a member)
    int seat_of_player(std::int64_t player_id) const; // -1 if none
    proto::Phase phase() const;
    const rules::MatchState& match() const { return match_; }
    std::int64_t seq() const { return seq_; }
    proto::RoomState room_state(int you) const;

private:
    struct SeatSlot {
        bool occupied = false;
        std::int64_t player_id = -1;
        std::string name;
        std::shared_ptr<Peer> peer; // null while dropped or for a bot
        std::shared_ptr<BotBrain> bot;
        std::optional<std::int64_t> grace_deadline_ms;
        bool wants_rematch = false;
        EmoteLimiter emotes; // per seat: a resumed player keeps the seat's limit
    };

    void broadcast(const proto::ServerMessage& message, MessageKind kind = MessageKind::Normal,
                   const Peer* except = nullptr);
    // Each member's room state; a newer one may replace it in a slow member's queue, except the
    // copy of `joiner`, which just entered: its first message in the room is always a room state.
    void broadcast_room_state(const Peer* joiner = nullptr);
    // The turn event for the current turn, to everyone.
    void broadcast_turn();
    void send_to(Peer& peer, const proto::ServerMessage& message);
    // A member who enters (joins, takes a seat, resumes one): the board now, and `paused` while
    // the match is paused.
    void send_keyframe(Peer& peer);
    void send_error(Peer& peer, std::string_view code, std::string message);
    std::vector<Peer*> members();

    // Game input from a seat for a turn: in_motion, wrong_phase before the game, then the rules'
    // turn check (rules::check_turn) as a wire error.
    std::optional<proto::Error> check_input(int seat, int turn) const;
    std::optional<proto::Error> play(int seat, const Shot& shot);
    // The one way into a seat, for players (slot.peer) and bots (slot.bot): the first free seat
    // in index order, or `seat` when it is >= 0; the game starts once every seat is taken.
    // Errors: room_full, bad_field (no such seat).
    std::optional<proto::Error> fill_seat(SeatSlot slot, int seat = -1);
    // A game starts (counted, journaled as match_id); the first turn's clock runs.
    void start_game(std::string match_id, std::string rematch_of = {});
    // Appends an entry to the current match's journal (if any); returns its seq (-1: none).
    std::int64_t journal(proto::JournalEntry entry, bool confirm = false);
    void journal_event(proto::JournalEvent event); // now, unconfirmed
    void journal_seat(int seat);                   // the seat's holder, to the sink
    std::int64_t wall_ms() const { return clock_.unix_ms(); }
    void start_turn();
    void stream_tick(std::int64_t now_ms);
    // Sends the stream's delta at t_s (and the events before it); true when the shot ended
    // (finish_shot ran and streaming_ is gone).
    bool send_stream_step(double t_s, std::int64_t due_ms);
    void finish_shot();
    // A running game is forfeited by seat (journaled; game_end's reason is wire_reason).
    void forfeit(int seat, proto::ForfeitReason reason, std::string_view wire_reason);
    void apply_non_stroke(const rules::PlayResult& result, std::string_view reason);
    void after_outcome(const rules::ShotOutcome& outcome, const rules::MatchState& before,
                       std::string_view reason_override = {});
    bool check_member_input(Peer& peer, int& seat);
    void free_seat(int seat);
    void notify(MembershipChange change, int seat, const std::string& name = {});
    void check_grace(std::int64_t now_ms);
    void check_shot_clock(std::int64_t now_ms);
    // The stroke's entry has waited store_pause_after_ms: `paused` to every member, once.
    void check_store_wait(std::int64_t now_ms);
    std::optional<std::int64_t> shot_clock_deadline_ms() const;
    std::vector<Body> board_with_striker() const;
    proto::Snapshot current_keyframe() const;
    bool game_running() const;

    std::string code_;
    RoomConfig config_;
    const Clock& clock_;
    RoomCounters& counters_;
    RoomObserver* observer_;
    JournalSink* journal_;
    std::string match_id_;         // the current game's journal ("" if none)
    std::int64_t journal_seq_ = 0; // the next entry's seq in it
    ExactEngine engine_;
    rules::MatchState match_;
    std::vector<SeatSlot> seats_; // one per seat of the rules (rules.seat_count)
    std::vector<std::shared_ptr<Peer>> spectators_;
    bool started_ = false; // a game has started (every seat was filled)
    std::int64_t turn_started_ms_ = 0;
    double aim_x_px_;      // the shooter's last aim position
    std::int64_t seq_ = 0; // last snapshot sequence number broadcast

    // The shot being streamed.
    struct Streaming {
        ShotStream stream;
        rules::PlayResult result;
        rules::MatchState before;
        std::int64_t start_ms = 0;
        std::int64_t next_ms = 0;      // next wake: the next change of motion or next_base_ms
        std::int64_t next_base_ms = 0; // next snapshot due at the regular rate
        int index = 0;                 // regular snapshots sent
        // The stroke's journal entry not yet confirmed written: nothing of it is streamed.
        // (It waits since start_ms.)
        std::optional<std::int64_t> awaiting_seq;
        // The members were told `paused` for this wait; they get `resumed` when it ends.
        bool paused = false;
    };
    std::unique_ptr<Streaming> streaming_;
    int bot_turn_taken_ = -1; // turn number whose BotTurn was handed out
};

} // namespace carrom::room
