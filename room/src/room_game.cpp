// Room: the game flow (input, the stroke, its stream and outcome, rematch, bot turns, the clocks).
// Construction, membership and messages are in room.cpp.
#include "carrom/room/room.hpp"

#include "carrom/proto/journal_replay.hpp"
#include "carrom/room/outcome_messages.hpp"
#include "carrom/room/snapshot_writer.hpp"

#include "room_support.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::room {

void Room::start_game(std::string match_id, std::string rematch_of) {
    started_ = true;
    counters_.matches.fetch_add(1, std::memory_order_relaxed);
    counters_.matches_started_total.fetch_add(1, std::memory_order_relaxed);
    match_id_ = std::move(match_id);
    journal_seq_ = 0;
    if (journal_ != nullptr && !match_id_.empty()) {
        proto::MatchCreated created;
        created.match_id = match_id_;
        created.rematch_of = std::move(rematch_of);
        created.room_code = code_;
        created.rule_set = to_rules(config_.rule_set);
        created.rules = config_.rules;
        created.physics = config_.physics;
        for (const SeatSlot& slot : seats_) {
            created.seats.push_back({slot.name, slot.bot != nullptr});
        }
        created.first_turn = match_.turn_number;
        created.versions.server = config_.server_version;
        created.time_ms = wall_ms();
        journal_->created(created);
        for (std::size_t i = 0; i < seats_.size(); ++i) {
            journal_seat(static_cast<int>(i));
        }
    }
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
        return make_error(proto::code::kWrongPhase, "The game starts when every seat is taken.");
    }
    if (auto error = rules::check_turn(match_, seat, turn)) {
        return to_proto_error(*error);
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

void Room::emote(Peer& peer, const proto::EmoteMessage& emote) {
    const int seat = seat_of(peer);
    if (seat < 0) {
        send_error(peer, is_member(peer) ? proto::code::kSpectator : proto::code::kNotInRoom,
                   "Only seated players can send emotes.");
        return;
    }
    if (!started_) {
        send_error(peer, proto::code::kWrongPhase, "Emotes can be sent once the game starts.");
        return;
    }
    if (!seats_[static_cast<std::size_t>(seat)].emotes.try_take(clock_.now_ms())) {
        send_error(peer, proto::code::kEmoteTooFast,
                   "Too many emotes; wait a moment before the next one.");
        return;
    }
    broadcast(proto::Event{proto::EmoteEvent{seat, emote.emote}}, MessageKind::Cue);
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
    // Journaled before anything is moved out of the result (its hash covers the events); the
    // stroke streams once the sink says the entry is written (journal_written).
    const std::int64_t seq = journal(proto::stroke_entry(wall_ms(), result), true);
    const std::int64_t now = clock_.now_ms();
    SimResult& physics = result.outcome.physics;
    ShotStream stream(config_.physics, std::move(physics.trajectory), std::move(physics.events),
                      physics.end_time_s, match_.turn_number);
    physics.trajectory = {};
    physics.events.clear();
    streaming_ = std::make_unique<Streaming>(Streaming{std::move(stream), std::move(result), match_,
                                                       now, now, now, 0, std::nullopt, false});
    if (seq >= 0) {
        streaming_->awaiting_seq = seq;
    } else {
        stream_tick(now);
    }
    return std::nullopt;
}

void Room::journal_written(const std::string& match_id, std::int64_t seq) {
    if (!streaming_ || streaming_->awaiting_seq != seq || match_id != match_id_) {
        return;
    }
    streaming_->awaiting_seq.reset();
    if (streaming_->paused) {
        broadcast(proto::Event{proto::ResumedEvent{}});
    }
    const std::int64_t now = clock_.now_ms();
    streaming_->start_ms = now;
    streaming_->next_ms = now;
    streaming_->next_base_ms = now;
    stream_tick(now);
}

void Room::stream_tick(std::int64_t now_ms) {
    if (!streaming_ || streaming_->awaiting_seq || now_ms < streaming_->next_ms) {
        return;
    }
    Streaming& s = *streaming_;
    counters_.observe_snapshot_lag_ms(static_cast<double>(now_ms - s.next_ms));
    const double t_s = config_.time_scale * static_cast<double>(now_ms - s.start_ms) / 1000.0;
    // The first whole millisecond at or after a stream time: when its delta is due.
    const auto due_ms = [&](double t) {
        return s.start_ms + static_cast<std::int64_t>(std::ceil(t / config_.time_scale * 1000.0));
    };
    // A delta at every change of motion since the last snapshot, at its own instant, then one at
    // t_s when the regular rate has one due (or the shot ends).
    if (config_.contact_snapshots) {
        while (const std::optional<double> change = s.stream.next_motion_change(t_s)) {
            if (send_stream_step(*change, due_ms(*change))) {
                return;
            }
        }
    }
    if (now_ms >= s.next_base_ms || t_s >= s.stream.end_time_s()) {
        if (send_stream_step(t_s, std::min(s.next_base_ms, due_ms(s.stream.end_time_s())))) {
            return;
        }
        const double period_ms = 1000.0 / config_.snapshot_hz;
        while (s.next_base_ms <= now_ms) {
            ++s.index;
            s.next_base_ms = s.start_ms + std::llround(s.index * period_ms);
        }
    }
    s.next_ms = s.next_base_ms;
    if (config_.contact_snapshots) {
        s.next_ms = std::min(s.next_ms, std::max(due_ms(s.stream.end_time_s()), now_ms + 1));
        const std::optional<double> change = s.stream.next_motion_change(s.stream.end_time_s());
        if (change) {
            // Never before the change: its delta is at its own instant, which must have passed.
            s.next_ms = std::min(s.next_ms, std::max(due_ms(*change), now_ms + 1));
        }
    }
}

bool Room::send_stream_step(double t_s, std::int64_t due_ms) {
    Streaming& s = *streaming_;
    ShotStream::Step step = s.stream.advance(t_s, ++seq_);
    step.snapshot.due_ms = due_ms;
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
        return true;
    }
    return false;
}

void Room::finish_shot() {
    std::unique_ptr<Streaming> done = std::move(streaming_);
    if (done->paused && done->awaiting_seq) { // a leave ends the stroke: the wait is over too
        broadcast(proto::Event{proto::ResumedEvent{}});
    }
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

void Room::forfeit(int seat, proto::ForfeitReason reason, std::string_view wire_reason) {
    if (!game_running()) {
        return;
    }
    const rules::PlayResult r = rules::forfeit(match_, seat);
    if (!r.error) {
        journal(proto::forfeit_entry(wall_ms(), r, reason));
        apply_non_stroke(r, wire_reason);
    }
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
    const proto::GameEndEvent* game_end = nullptr;
    for (auto& event : events) {
        if (auto* end = std::get_if<proto::GameEndEvent>(&event)) {
            if (!reason_override.empty()) {
                end->reason = std::string(reason_override);
            }
            game_end = end;
        }
        broadcast(event);
    }
    if (was_running && match_.phase == rules::Phase::GameOver) {
        counters_.matches.fetch_sub(1, std::memory_order_relaxed);
        counters_.matches_finished_total.fetch_add(1, std::memory_order_relaxed);
        if (observer_ != nullptr && game_end != nullptr) {
            observer_->game_over(*game_end);
        }
    }
    start_turn();
    bot_turn_taken_ = -1;
    broadcast_room_state();
    if (match_.phase != rules::Phase::GameOver) {
        broadcast_turn();
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
    std::string next_id = journal_ != nullptr ? journal_->next_match_id() : std::string{};
    journal_event(proto::RematchEntry{next_id});
    const int next_turn = match_.turn_number + 1;
    // The next seat breaks the next game (anticlockwise, as the turn passes).
    config_.rules.first_breaker = rules::next_seat(config_.rules.first_breaker, seat_count());
    match_ = rules::new_match(to_rules(config_.rule_set), config_.rules, config_.physics);
    match_.turn_number = next_turn;
    start_game(std::move(next_id), match_id_);
    bot_turn_taken_ = -1;
    broadcast_room_state();
    ++seq_; // the new game's board is a new broadcast snapshot
    broadcast(current_keyframe());
    broadcast_turn();
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

BotShotOutcome Room::bot_shoot(int seat, int turn, const Shot& shot) {
    if (seat < 0 || seat >= static_cast<int>(seats_.size()) ||
        !seats_[static_cast<std::size_t>(seat)].bot) {
        return {make_error(proto::code::kNotYourTurn, "That seat has no bot."), std::nullopt};
    }
    if (auto error = check_input(seat, turn)) {
        return {std::move(error), std::nullopt};
    }
    auto error = play(seat, shot);
    if (!error) {
        return {};
    }
    if (const auto legal = rules::nearest_legal_shot(match_, seat, shot)) {
        if (!play(seat, *legal)) {
            return {std::nullopt, std::move(error)};
        }
    }
    return {std::move(error), std::nullopt}; // a baseline with no free position
}

// --- time -------------------------------------------------------------------------------------

void Room::check_grace(std::int64_t now_ms) {
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        SeatSlot& slot = seats_[i];
        if (!slot.occupied || !slot.grace_deadline_ms || now_ms < *slot.grace_deadline_ms) {
            continue;
        }
        notify(MembershipChange::Left, static_cast<int>(i)); // the grace period is over
        forfeit(static_cast<int>(i), proto::ForfeitReason::GraceExpired, "forfeit");
        journal_event(proto::SeatLeftEntry{static_cast<int>(i)});
        free_seat(static_cast<int>(i));
        journal_seat(static_cast<int>(i));
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
        journal(proto::clock_expired_entry(wall_ms(), r));
        apply_non_stroke(r, {});
    }
}

void Room::check_store_wait(std::int64_t now_ms) {
    if (!streaming_ || !streaming_->awaiting_seq || streaming_->paused ||
        now_ms < streaming_->start_ms + config_.store_pause_after_ms) {
        return;
    }
    streaming_->paused = true;
    broadcast(store_paused_event());
}

void Room::tick() {
    const std::int64_t now = clock_.now_ms();
    check_store_wait(now);
    stream_tick(now);
    if (streaming_) {
        return;
    }
    check_grace(now);
    check_shot_clock(now);
}

std::optional<std::int64_t> Room::next_wake_ms() const {
    if (streaming_) {
        if (streaming_->awaiting_seq) { // journal_written wakes the room; `paused` is due first
            return streaming_->paused
                       ? std::nullopt
                       : std::optional(streaming_->start_ms + config_.store_pause_after_ms);
        }
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
