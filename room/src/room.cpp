#include "carrom/room/room.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/room/outcome_messages.hpp"
#include "carrom/room/snapshot_writer.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::room {

namespace {

Baseline to_baseline(rules::Side side) {
    return side == rules::Side::Top ? Baseline::Top : Baseline::Bottom;
}

proto::Error make_error(std::string_view code, std::string message) {
    return {std::string(code), std::move(message)};
}

std::int64_t seconds_to_ms(double s) {
    return static_cast<std::int64_t>(std::llround(s * 1000.0));
}

} // namespace

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

Room::Room(std::string code, RoomConfig config, const Clock& clock, RoomCounters& counters)
    : code_(std::move(code)), config_(std::move(config)), clock_(clock), counters_(counters),
      engine_(config_.physics),
      match_(rules::new_match(to_rules(config_.rule_set), config_.rules, config_.physics)),
      aim_x_px_(config_.physics.centre().x) {}

Room::~Room() {
    if (game_running()) {
        counters_.matches.fetch_sub(1, std::memory_order_relaxed);
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
    bool started_now = false;
    if (role == proto::Role::Player) {
        auto free = std::find_if(seats_.begin(), seats_.end(),
                                 [](const SeatSlot& s) { return !s.occupied; });
        if (free == seats_.end()) {
            return make_error(proto::code::kRoomFull,
                              "Both seats are taken; join as a spectator instead.");
        }
        free->occupied = true;
        free->player_id = peer->player_id();
        free->name = peer->name();
        free->peer = peer;
        started_now = !started_ && seats_[0].occupied && seats_[1].occupied;
        if (started_now) {
            start_game_if_ready();
        }
    } else {
        spectators_.push_back(peer);
    }
    broadcast_room_state();
    send_to(*peer, current_keyframe());
    if (started_now) {
        broadcast(proto::Event{proto::TurnEvent{match_.turn_number, match_.turn_seat,
                                                shot_clock_deadline_ms(), clock_.now_ms()}});
    }
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
    }
    broadcast_room_state();
    send_to(*peer, current_keyframe());
    return std::nullopt;
}

std::optional<proto::Error> Room::seat_bot(std::string name, std::shared_ptr<BotBrain> brain) {
    auto free =
        std::find_if(seats_.begin(), seats_.end(), [](const SeatSlot& s) { return !s.occupied; });
    if (free == seats_.end()) {
        return make_error(proto::code::kRoomFull, "Both seats are taken.");
    }
    free->occupied = true;
    free->player_id = -1;
    free->name = std::move(name);
    free->bot = std::move(brain);
    const bool started_now = !started_ && seats_[0].occupied && seats_[1].occupied;
    if (started_now) {
        start_game_if_ready();
    }
    broadcast_room_state();
    if (started_now) {
        broadcast(proto::Event{proto::TurnEvent{match_.turn_number, match_.turn_seat,
                                                shot_clock_deadline_ms(), clock_.now_ms()}});
    }
    return std::nullopt;
}

void Room::leave(const Peer& peer) {
    const int seat = seat_of(peer);
    if (seat < 0) {
        const auto before = spectators_.size();
        std::erase_if(spectators_, [&](const auto& s) { return s.get() == &peer; });
        if (spectators_.size() != before) {
            broadcast_room_state();
        }
        return;
    }
    if (streaming_) {
        finish_shot();
    }
    if (game_running()) {
        const rules::PlayResult r = rules::forfeit(match_, seat);
        if (!r.error) {
            apply_non_stroke(r, "left");
        }
    }
    free_seat(seat);
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
    broadcast_room_state();
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

// --- messages ---------------------------------------------------------------------------------

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

void Room::broadcast_room_state() {
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        if (seats_[i].peer) {
            send_to(*seats_[i].peer, room_state(static_cast<int>(i)));
        }
    }
    if (!spectators_.empty()) {
        auto text = std::make_shared<const std::string>(proto::encode(room_state(-1)));
        for (auto& s : spectators_) {
            s->send({text, MessageKind::Normal});
        }
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
        info.baseline = to_baseline(match_.seats[i].side);
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
    state.phase = phase();
    state.queen = to_proto(match_.queen);
    state.winner = match_.result && match_.result->winner_team ? *match_.result->winner_team : -1;
    for (const Body& body : board_with_striker()) {
        state.bodies.push_back(proto::to_board_body(body));
    }
    return state;
}

// --- game -------------------------------------------------------------------------------------

void Room::start_game_if_ready() {
    started_ = true;
    counters_.matches.fetch_add(1, std::memory_order_relaxed);
    counters_.matches_started_total.fetch_add(1, std::memory_order_relaxed);
    start_turn();
}

void Room::start_turn() {
    turn_started_ms_ = clock_.now_ms();
    aim_x_px_ = config_.physics.centre().x;
}

std::optional<proto::Error> Room::check_input(int seat, int turn) const {
    if (streaming_) {
        return make_error(proto::code::kInMotion, "Wait until the pieces stop.");
    }
    if (!started_) {
        return make_error(proto::code::kWrongPhase, "The game starts when both seats are taken.");
    }
    if (match_.phase == rules::Phase::GameOver) {
        return make_error(proto::code::kWrongPhase, "The game is over.");
    }
    if (seat != match_.turn_seat) {
        return make_error(proto::code::kNotYourTurn,
                          "It is seat " + std::to_string(match_.turn_seat) + "'s turn.");
    }
    if (turn != match_.turn_number) {
        return make_error(proto::code::kStaleTurn, "That input was for turn " +
                                                       std::to_string(turn) + "; the turn is " +
                                                       std::to_string(match_.turn_number) + ".");
    }
    return std::nullopt;
}

bool Room::check_member_input(Peer& peer, int& seat) {
    seat = seat_of(peer);
    if (seat >= 0) {
        return true;
    }
    if (is_member(peer)) {
        send_error(peer, proto::code::kSpectator, "Spectators cannot play.");
    } else {
        send_error(peer, proto::code::kNotInRoom, "You are not in this room.");
    }
    return false;
}

void Room::aim(Peer& peer, const proto::Aim& aim) {
    int seat = -1;
    if (!check_member_input(peer, seat)) {
        return;
    }
    if (auto error = check_input(seat, aim.turn)) {
        send_error(peer, error->code, error->message);
        return;
    }
    aim_x_px_ = aim.x_px;
    broadcast(proto::Event{proto::AimEvent{seat, aim.turn, aim.x_px}}, MessageKind::Cue, &peer);
}

void Room::shoot(Peer& peer, const proto::Shoot& shoot) {
    int seat = -1;
    if (!check_member_input(peer, seat)) {
        return;
    }
    auto error = check_input(seat, shoot.turn);
    if (!error) {
        error = play(seat, Shot{shoot.x_px, shoot.angle_rad, shoot.power});
    }
    if (error) {
        send_error(peer, error->code, error->message);
    }
}

std::optional<proto::Error> Room::play(int seat, const Shot& shot) {
    rules::PlayOptions options;
    options.record_trajectory = true;
    rules::PlayResult result = rules::play_shot(match_, seat, shot, engine_, options);
    if (result.error) {
        return to_proto_error(*result.error);
    }
    counters_.shots_total.fetch_add(1, std::memory_order_relaxed);
    const std::int64_t now = clock_.now_ms();
    SimResult& physics = result.outcome.physics;
    ShotStream stream(config_.physics, std::move(physics.trajectory), std::move(physics.events),
                      physics.end_time_s, match_.turn_number);
    physics.trajectory = {};
    physics.events.clear();
    streaming_ = std::make_unique<Streaming>(
        Streaming{std::move(stream), std::move(result), match_, now, now, 0});
    stream_tick(now);
    return std::nullopt;
}

void Room::stream_tick(std::int64_t now_ms) {
    if (!streaming_ || now_ms < streaming_->next_ms) {
        return;
    }
    Streaming& s = *streaming_;
    counters_.observe_snapshot_lag_ms(static_cast<double>(now_ms - s.next_ms));
    const double t_s = config_.time_scale * static_cast<double>(now_ms - s.start_ms) / 1000.0;
    ShotStream::Step step = s.stream.advance(t_s, ++seq_);
    step.snapshot.due_ms = s.next_ms;
    for (auto& event : step.events) {
        const bool pocket = std::holds_alternative<proto::PocketEvent>(event);
        broadcast(proto::ServerMessage{std::move(event)},
                  pocket ? MessageKind::Normal : MessageKind::Cue);
    }
    counters_.snapshots_total.fetch_add(1, std::memory_order_relaxed);
    auto delta = std::make_shared<const std::string>(encode_snapshot(step.snapshot));
    std::shared_ptr<const std::string> keyframe;
    for (Peer* peer : members()) {
        if (peer->take_keyframe_request()) {
            if (!keyframe) {
                keyframe =
                    std::make_shared<const std::string>(encode_snapshot(s.stream.keyframe(seq_)));
            }
            peer->send({keyframe, MessageKind::Snapshot});
        } else {
            peer->send({delta, MessageKind::Snapshot});
        }
    }
    if (step.finished) {
        finish_shot();
        return;
    }
    const double period_ms = 1000.0 / config_.snapshot_hz;
    while (s.next_ms <= now_ms) {
        ++s.index;
        s.next_ms = s.start_ms + std::llround(s.index * period_ms);
    }
}

void Room::finish_shot() {
    std::unique_ptr<Streaming> done = std::move(streaming_);
    const double end_s = done->stream.end_time_s();
    match_ = std::move(done->result.state);
    ++seq_;
    const int turn = done->result.outcome.turn_number;
    // The board as the rules left it (returned pieces placed), the striker on the next
    // shooter's baseline. After a board ends, the next board's layout follows in room_state.
    aim_x_px_ = config_.physics.centre().x;
    broadcast(make_keyframe(board_with_striker(), seq_, turn, end_s));
    after_outcome(done->result.outcome, done->before);
}

void Room::apply_non_stroke(const rules::PlayResult& result, std::string_view reason) {
    const rules::MatchState before = match_;
    match_ = result.state;
    after_outcome(result.outcome, before, reason);
}

void Room::after_outcome(const rules::ShotOutcome& outcome, const rules::MatchState& before,
                         std::string_view reason_override) {
    const bool was_running = before.phase != rules::Phase::GameOver;
    std::vector<proto::Event> events = rule_events(outcome, before, match_);
    if (match_.phase == rules::Phase::BoardOver) {
        match_ = rules::start_next_board(match_);
    }
    broadcast(to_shot_result(outcome, match_));
    for (auto& event : events) {
        if (auto* end = std::get_if<proto::GameEndEvent>(&event); end && !reason_override.empty()) {
            end->reason = std::string(reason_override);
        }
        broadcast(event);
    }
    if (was_running && match_.phase == rules::Phase::GameOver) {
        counters_.matches.fetch_sub(1, std::memory_order_relaxed);
        counters_.matches_finished_total.fetch_add(1, std::memory_order_relaxed);
    }
    start_turn();
    bot_turn_taken_ = -1;
    broadcast_room_state();
    if (match_.phase != rules::Phase::GameOver) {
        broadcast(proto::Event{proto::TurnEvent{match_.turn_number, match_.turn_seat,
                                                shot_clock_deadline_ms(), clock_.now_ms()}});
    }
}

void Room::rematch(Peer& peer) {
    const int seat = seat_of(peer);
    if (seat < 0) {
        send_error(peer, is_member(peer) ? proto::code::kSpectator : proto::code::kNotInRoom,
                   "Only seated players can ask for a rematch.");
        return;
    }
    if (match_.phase != rules::Phase::GameOver) {
        send_error(peer, proto::code::kWrongPhase, "A rematch is possible after the game ends.");
        return;
    }
    seats_[static_cast<std::size_t>(seat)].wants_rematch = true;
    const bool all = std::all_of(seats_.begin(), seats_.end(), [](const SeatSlot& s) {
        return s.occupied && (s.wants_rematch || s.bot != nullptr);
    });
    if (!all) {
        return;
    }
    for (auto& s : seats_) {
        s.wants_rematch = false;
    }
    const int next_turn = match_.turn_number + 1;
    config_.rules.first_breaker = (config_.rules.first_breaker + 1) % 2;
    match_ = rules::new_match(to_rules(config_.rule_set), config_.rules, config_.physics);
    match_.turn_number = next_turn;
    counters_.matches.fetch_add(1, std::memory_order_relaxed);
    counters_.matches_started_total.fetch_add(1, std::memory_order_relaxed);
    start_turn();
    bot_turn_taken_ = -1;
    broadcast_room_state();
    broadcast(current_keyframe());
    broadcast(proto::Event{proto::TurnEvent{match_.turn_number, match_.turn_seat,
                                            shot_clock_deadline_ms(), clock_.now_ms()}});
}

// --- bots -------------------------------------------------------------------------------------

std::optional<BotTurn> Room::take_bot_turn() {
    if (!game_running() || streaming_ || bot_turn_taken_ == match_.turn_number) {
        return std::nullopt;
    }
    const SeatSlot& slot = seats_[static_cast<std::size_t>(match_.turn_seat)];
    if (!slot.occupied || !slot.bot) {
        return std::nullopt;
    }
    bot_turn_taken_ = match_.turn_number;
    return BotTurn{match_.turn_seat, match_.turn_number, match_, slot.bot};
}

std::optional<proto::Error> Room::bot_shoot(int seat, int turn, const Shot& shot) {
    if (seat < 0 || seat >= static_cast<int>(seats_.size()) ||
        !seats_[static_cast<std::size_t>(seat)].bot) {
        return make_error(proto::code::kNotYourTurn, "That seat has no bot.");
    }
    if (auto error = check_input(seat, turn)) {
        return error;
    }
    return play(seat, shot);
}

// --- time -------------------------------------------------------------------------------------

void Room::check_grace(std::int64_t now_ms) {
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        SeatSlot& slot = seats_[i];
        if (!slot.occupied || !slot.grace_deadline_ms || now_ms < *slot.grace_deadline_ms) {
            continue;
        }
        if (game_running()) {
            const rules::PlayResult r = rules::forfeit(match_, static_cast<int>(i));
            if (!r.error) {
                apply_non_stroke(r, "forfeit");
            }
        }
        free_seat(static_cast<int>(i));
        broadcast_room_state();
    }
}

void Room::check_shot_clock(std::int64_t now_ms) {
    if (!game_running() || streaming_ || match_.config.shot_clock_s <= 0.0) {
        return;
    }
    const double elapsed_s = static_cast<double>(now_ms - turn_started_ms_) / 1000.0;
    if (!rules::shot_clock_ran_out(match_, elapsed_s)) {
        return;
    }
    const rules::PlayResult r = rules::shot_clock_expired(match_, match_.turn_seat);
    if (!r.error) {
        apply_non_stroke(r, {});
    }
}

void Room::tick() {
    const std::int64_t now = clock_.now_ms();
    stream_tick(now);
    if (streaming_) {
        return;
    }
    check_grace(now);
    check_shot_clock(now);
}

std::optional<std::int64_t> Room::next_wake_ms() const {
    if (streaming_) {
        return streaming_->next_ms;
    }
    std::optional<std::int64_t> wake;
    auto consider = [&](std::int64_t t) { wake = wake ? std::min(*wake, t) : t; };
    for (const SeatSlot& slot : seats_) {
        if (slot.occupied && slot.grace_deadline_ms) {
            consider(*slot.grace_deadline_ms);
        }
    }
    if (game_running() && match_.config.shot_clock_s > 0.0) {
        // shot_clock_ran_out is strict: one millisecond past clock + grace.
        consider(turn_started_ms_ +
                 seconds_to_ms(match_.config.shot_clock_s + match_.config.shot_clock_grace_s) + 1);
    }
    return wake;
}

} // namespace carrom::room
