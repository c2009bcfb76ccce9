// Room: construction, membership (seats, spectators, grace) and what the room says (messages and
// views of its state). The game flow is in room_game.cpp.
#include "carrom/room/room.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/room/outcome_messages.hpp"

#include "room_support.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::room {

rules::RulesConfig make_rules_config(proto::RuleSet rule_set, const proto::RoomOptions& options,
                                     double default_shot_clock_s) {
    rules::RulesConfig config;
    config.shot_clock_s = default_shot_clock_s;
    if (options.target_points) {
        if (rule_set == proto::RuleSet::Freestyle) {
            config.freestyle.target = *options.target_points;
        } else {
            config.target_points = *options.target_points;
        }
    }
    if (options.boards) {
        config.max_boards = *options.boards;
    }
    if (options.shot_clock_s) {
        config.shot_clock_s = *options.shot_clock_s;
    }
    return config;
}

Room::Room(std::string code, RoomConfig config, const Clock& clock, RoomCounters& counters,
           RoomObserver* observer, JournalSink* journal)
    : code_(std::move(code)), config_(std::move(config)), clock_(clock), counters_(counters),
      observer_(observer), journal_(journal), engine_(config_.physics),
      match_(rules::new_match(to_rules(config_.rule_set), config_.rules, config_.physics)),
      seats_(match_.seats.size()), aim_x_px_(config_.physics.centre().x) {}

Room::~Room() {
    if (game_running()) {
        counters_.matches.fetch_sub(1, std::memory_order_relaxed);
        if (journal_ != nullptr && !match_id_.empty()) {
            journal_->abandoned(match_id_);
        }
    }
}

// --- membership -------------------------------------------------------------------------------

bool Room::is_member(const Peer& peer) const {
    if (seat_of(peer) >= 0) {
        return true;
    }
    return std::any_of(spectators_.begin(), spectators_.end(),
                       [&](const auto& s) { return s.get() == &peer; });
}

int Room::seat_of(const Peer& peer) const {
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        if (seats_[i].occupied && seats_[i].peer.get() == &peer) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

int Room::seat_of_player(std::int64_t player_id) const {
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        if (seats_[i].occupied && !seats_[i].bot && seats_[i].player_id == player_id) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

std::optional<proto::Error> Room::join(std::shared_ptr<Peer> peer, proto::Role role) {
    if (is_member(*peer) || seat_of_player(peer->player_id()) >= 0) {
        return make_error(proto::code::kAlreadyInRoom, "You are already in this room.");
    }
    if (role == proto::Role::Player) {
        SeatSlot slot;
        slot.player_id = peer->player_id();
        slot.name = peer->name();
        slot.peer = peer;
        return fill_seat(std::move(slot));
    }
    // Only the newcomer gets the room state: spectators coming and going send nothing to the
    // others (their count reaches them with the next room_state), so joining and leaving cannot
    // flood the players' connections.
    spectators_.push_back(peer);
    send_to(*peer, room_state(-1));
    send_keyframe(*peer);
    notify(MembershipChange::Joined, -1, peer->name());
    return std::nullopt;
}

std::optional<proto::Error> Room::resume(std::shared_ptr<Peer> peer) {
    const int seat = seat_of_player(peer->player_id());
    if (seat < 0) {
        return make_error(proto::code::kBadToken, "That seat is no longer yours.");
    }
    SeatSlot& slot = seats_[static_cast<std::size_t>(seat)];
    const bool was_dropped = slot.peer == nullptr;
    if (slot.peer && slot.peer != peer) {
        send_error(*slot.peer, proto::code::kReplaced,
                   "Your seat was resumed on another connection.");
        slot.peer->close(proto::kCloseReplaced, "replaced");
    }
    slot.peer = peer;
    slot.name = peer->name();
    slot.grace_deadline_ms.reset();
    if (was_dropped) {
        broadcast(proto::Event{proto::PlayerReturnedEvent{seat}}, MessageKind::Normal, peer.get());
        journal_event(proto::SeatReturnedEntry{seat});
    }
    journal_seat(seat);
    broadcast_room_state(peer.get());
    send_keyframe(*peer);
    notify(MembershipChange::Returned, seat);
    return std::nullopt;
}

std::optional<proto::Error> Room::seat_bot(std::string name, std::shared_ptr<BotBrain> brain,
                                           int seat) {
    SeatSlot slot;
    slot.name = std::move(name);
    slot.bot = std::move(brain);
    return fill_seat(std::move(slot), seat);
}

std::optional<proto::Error> Room::fill_seat(SeatSlot slot, int seat_index) {
    auto free =
        std::find_if(seats_.begin(), seats_.end(), [](const SeatSlot& s) { return !s.occupied; });
    if (seat_index >= 0) {
        if (seat_index >= seat_count()) {
            return make_error(proto::code::kBadField,
                              "This room has no seat " + std::to_string(seat_index) + ".");
        }
        free = seats_.begin() + seat_index;
        if (free->occupied) {
            return make_error(proto::code::kRoomFull,
                              "Seat " + std::to_string(seat_index) + " is taken.");
        }
    }
    if (free == seats_.end()) {
        return make_error(proto::code::kRoomFull,
                          "Every seat is taken; join as a spectator instead.");
    }
    *free = std::move(slot);
    free->occupied = true;
    const int seat = static_cast<int>(free - seats_.begin());
    const bool started_now = !started_ && std::all_of(seats_.begin(), seats_.end(),
                                                      [](const SeatSlot& s) { return s.occupied; });
    if (started_now) {
        start_game(journal_ != nullptr ? journal_->next_match_id() : std::string{});
    } else {
        journal_event(proto::SeatJoinedEntry{seat, free->name, free->bot != nullptr});
        journal_seat(seat);
    }
    broadcast_room_state(free->peer.get());
    if (free->peer) {
        send_keyframe(*free->peer);
    }
    if (started_now) {
        broadcast_turn();
    }
    notify(MembershipChange::Joined, seat);
    return std::nullopt;
}

void Room::leave(const Peer& peer) {
    const int seat = seat_of(peer);
    if (seat < 0) {
        const auto before = spectators_.size();
        std::erase_if(spectators_, [&](const auto& s) { return s.get() == &peer; });
        if (spectators_.size() != before) {
            notify(MembershipChange::Left, -1, peer.name());
        }
        return;
    }
    notify(MembershipChange::Left, seat);
    if (streaming_) {
        finish_shot();
    }
    forfeit(seat, proto::ForfeitReason::Left, "left");
    journal_event(proto::SeatLeftEntry{seat});
    free_seat(seat);
    journal_seat(seat);
    broadcast_room_state();
}

void Room::disconnected(const Peer& peer) {
    const int seat = seat_of(peer);
    if (seat < 0) {
        leave(peer); // a spectator (or nobody)
        return;
    }
    SeatSlot& slot = seats_[static_cast<std::size_t>(seat)];
    slot.peer.reset();
    const std::int64_t now = clock_.now_ms();
    slot.grace_deadline_ms = now + seconds_to_ms(config_.grace_s);
    broadcast(proto::Event{proto::PlayerDroppedEvent{seat, *slot.grace_deadline_ms, now}});
    journal_event(proto::SeatDroppedEntry{seat});
    broadcast_room_state();
    notify(MembershipChange::Dropped, seat);
}

void Room::notify(MembershipChange change, int seat, const std::string& name) {
    if (observer_ == nullptr) {
        return;
    }
    MemberNotice notice{change, name, seat, false};
    if (seat >= 0) {
        const SeatSlot& slot = seats_[static_cast<std::size_t>(seat)];
        notice.name = slot.name;
        notice.bot = slot.bot != nullptr;
    }
    observer_->member(notice);
}

std::int64_t Room::journal(proto::JournalEntry entry, bool confirm) {
    if (journal_ == nullptr || match_id_.empty()) {
        return -1;
    }
    const std::int64_t seq = journal_seq_++;
    journal_->append(match_id_, seq, entry, confirm);
    return seq;
}

void Room::journal_event(proto::JournalEvent event) {
    journal(proto::JournalEntry{wall_ms(), std::move(event)});
}

void Room::journal_seat(int seat) {
    if (journal_ == nullptr || match_id_.empty()) {
        return;
    }
    const SeatSlot& slot = seats_[static_cast<std::size_t>(seat)];
    journal_->seat_holder(match_id_, seat,
                          slot.occupied && slot.peer ? slot.peer->resume_token() : std::string{});
}

void Room::free_seat(int seat) {
    SeatSlot& slot = seats_[static_cast<std::size_t>(seat)];
    slot = SeatSlot{};
}

bool Room::abandoned() const {
    const bool human_seated = std::any_of(seats_.begin(), seats_.end(), [](const SeatSlot& s) {
        return s.occupied && s.bot == nullptr;
    });
    return !human_seated && spectators_.empty();
}

bool Room::waiting_for_players() const {
    const bool bot_seated = std::any_of(seats_.begin(), seats_.end(), [](const SeatSlot& s) {
        return s.occupied && s.bot != nullptr;
    });
    return !started_ && !bot_seated && !abandoned();
}

// --- messages ---------------------------------------------------------------------------------

void Room::close_connections(int close_code, const std::string& reason) {
    for (Peer* peer : members()) {
        peer->close(close_code, reason);
    }
}

std::vector<Peer*> Room::members() {
    std::vector<Peer*> out;
    for (auto& seat : seats_) {
        if (seat.peer) {
            out.push_back(seat.peer.get());
        }
    }
    for (auto& s : spectators_) {
        out.push_back(s.get());
    }
    return out;
}

void Room::broadcast(const proto::ServerMessage& message, MessageKind kind, const Peer* except) {
    auto text = std::make_shared<const std::string>(proto::encode(message));
    for (Peer* peer : members()) {
        if (peer != except) {
            peer->send({text, kind});
        }
    }
}

void Room::broadcast_room_state(const Peer* joiner) {
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        if (seats_[i].peer) {
            seats_[i].peer->send(
                {std::make_shared<const std::string>(
                     proto::encode(room_state(static_cast<int>(i)))),
                 seats_[i].peer.get() == joiner ? MessageKind::Normal : MessageKind::State});
        }
    }
    if (!spectators_.empty()) {
        auto text = std::make_shared<const std::string>(proto::encode(room_state(-1)));
        for (auto& s : spectators_) {
            s->send({text, MessageKind::State});
        }
    }
}

void Room::broadcast_turn() {
    broadcast(proto::Event{proto::TurnEvent{match_.turn_number, match_.turn_seat,
                                            shot_clock_deadline_ms(), clock_.now_ms()}});
}

void Room::send_keyframe(Peer& peer) {
    send_to(peer, current_keyframe());
    if (streaming_ && streaming_->paused) { // the newcomer hears of the pause too
        send_to(peer, store_paused_event());
    }
}

void Room::send_to(Peer& peer, const proto::ServerMessage& message) {
    peer.send({std::make_shared<const std::string>(proto::encode(message)), MessageKind::Normal});
}

void Room::send_error(Peer& peer, std::string_view code, std::string message) {
    counters_.errors_sent_total.fetch_add(1, std::memory_order_relaxed);
    send_to(peer, make_error(code, std::move(message)));
}

// --- state views ------------------------------------------------------------------------------

bool Room::game_running() const {
    return started_ && match_.phase != rules::Phase::GameOver;
}

proto::Phase Room::phase() const {
    if (streaming_) {
        return proto::Phase::Moving;
    }
    if (!started_) {
        return proto::Phase::Waiting;
    }
    switch (match_.phase) {
    case rules::Phase::GameOver:
        return proto::Phase::GameOver;
    case rules::Phase::BoardOver:
        return proto::Phase::BoardOver;
    case rules::Phase::AwaitingShot:
        break;
    }
    return proto::Phase::Aiming;
}

std::optional<std::int64_t> Room::shot_clock_deadline_ms() const {
    if (!game_running() || streaming_ || match_.config.shot_clock_s <= 0.0) {
        return std::nullopt;
    }
    return turn_started_ms_ + seconds_to_ms(match_.config.shot_clock_s);
}

std::vector<Body> Room::board_with_striker() const {
    std::vector<Body> bodies = match_.bodies;
    const auto& seat = match_.seats[static_cast<std::size_t>(match_.turn_seat)];
    const double x =
        std::clamp(aim_x_px_, baseline_x_min(config_.physics), baseline_x_max(config_.physics));
    bodies.push_back(rules::striker_for(config_.physics, seat.side, Shot{x, 0.0, 0.0}));
    return bodies;
}

proto::Snapshot Room::current_keyframe() const {
    if (streaming_) {
        return streaming_->stream.keyframe(seq_);
    }
    return make_keyframe(board_with_striker(), seq_, match_.turn_number, 0.0);
}

proto::RoomState Room::room_state(int you) const {
    proto::RoomState state;
    state.code = code_;
    state.you = you;
    state.rule_set = config_.rule_set;
    state.options.target_points = config_.rule_set == proto::RuleSet::Freestyle
                                      ? match_.config.freestyle.target
                                      : match_.config.target_points;
    state.options.boards = match_.config.max_boards;
    state.options.shot_clock_s = match_.config.shot_clock_s;
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        const SeatSlot& slot = seats_[i];
        proto::SeatInfo info;
        info.occupied = slot.occupied;
        info.name = slot.name;
        info.connected = slot.occupied && (slot.peer != nullptr || slot.bot != nullptr);
        info.bot = slot.bot != nullptr;
        info.colour = colour_of_team(match_, rules::team_of(match_, static_cast<int>(i)));
        info.baseline = match_.seats[i].side;
        info.team = match_.seats[i].team;
        state.seats.push_back(std::move(info));
    }
    state.spectators = static_cast<int>(spectators_.size());
    state.scores = per_seat(match_, match_.scores);
    state.dues = per_seat(match_, match_.dues_owed);
    state.board_number = match_.board;
    state.turn = match_.turn_number;
    state.to_play = match_.turn_seat;
    state.shot_clock_deadline_ms = shot_clock_deadline_ms();
    state.server_time_ms = clock_.now_ms();
    state.motion = {config_.physics.damping_per_s, config_.contact_snapshots};
    state.aim_assist = config_.aim_assist;
    state.phase = phase();
    state.queen = to_proto(match_.queen);
    state.winner = match_.result && match_.result->winner_team ? *match_.result->winner_team : -1;
    for (const Body& body : board_with_striker()) {
        state.bodies.push_back(proto::to_board_body(body));
    }
    return state;
}

} // namespace carrom::room
