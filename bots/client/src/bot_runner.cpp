#include "carrom/bots/bot_runner.hpp"

#include "carrom/bots/match_view.hpp"
#include "carrom/overloaded.hpp"
#include "carrom/rules/seat.hpp"

#include <algorithm>
#include <thread>

namespace carrom::bots {

namespace {

bool is_game_input_error(const std::string& code) {
    return code == proto::code::kIllegalPlacement || code == proto::code::kIllegalShot ||
           code == proto::code::kStaleTurn || code == proto::code::kNotYourTurn ||
           code == proto::code::kInMotion || code == proto::code::kWrongPhase;
}

// Errors after which this bot cannot get where it was going.
bool is_fatal_error(const std::string& code) {
    return code == proto::code::kRoomNotFound || code == proto::code::kRoomFull ||
           code == proto::code::kTooManyRooms || code == proto::code::kVersionMismatch ||
           code == proto::code::kServerFull || code == proto::code::kAlreadyInRoom ||
           code == proto::code::kUnsupported || code == proto::code::kReplaced ||
           code == proto::code::kSpectator;
}

// Seconds with one decimal, for sentences.
std::string seconds_text(std::chrono::milliseconds ms) {
    const auto tenths = (ms.count() + 50) / 100;
    return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10) + " s";
}

} // namespace

BotRunner::BotRunner(BotConfig config, Strategy& strategy)
    : config_(std::move(config)), strategy_(strategy), backoff_(config_.reconnect) {}

BotRunner::~BotRunner() = default;

void BotRunner::start() {
    connection_ =
        connect ? connect(config_) : net::Connection::open(config_.url, config_.connection);
    connection_->send(
        proto::Hello{proto::kProtocolVersion, config_.name,
                     token_.empty() ? std::nullopt : std::optional<std::string>(token_)});
}

bool BotRunner::step(std::chrono::milliseconds wait) {
    if (!connection_ || done()) {
        return done();
    }
    if (waiting_) {
        const auto now = net::Backoff::Clock::now();
        if (now < next_try_) {
            std::this_thread::sleep_for(
                std::min<net::Backoff::Clock::duration>(next_try_ - now, wait));
            return done();
        }
        try_resume();
        return done();
    }
    connection_->wait(wait);
    for (const auto& message : connection_->poll()) {
        if (on_message) {
            on_message(message);
        }
        handle(message);
        if (done()) {
            break;
        }
    }
    summary_.decode_errors = connection_->decode_errors();
    const auto status = connection_->status();
    if (!done() && !dropped_ && status.state == net::ConnectionState::Closed) {
        connection_lost(status);
    }
    return done();
}

void BotRunner::connection_lost(const net::ConnectionStatus& status) {
    const auto now = net::Backoff::Clock::now();
    const bool in_room = !token_.empty() && room_.has_value();
    if (!reconnecting_) {
        if (!config_.auto_resume || !in_room) {
            fail(status.detail);
            return;
        }
        reconnecting_ = true;
        backoff_.start(now);
        notice("Connection lost: " + status.detail + " Resuming " + seat_words() + " for up to " +
               seconds_text(config_.reconnect.give_up_after) + ".");
    }
    lost_reason_ = status.detail;
    resuming_ = false;
    if (backoff_.expired(now)) {
        fail("Gave up resuming " + seat_words() + " after " +
             seconds_text(
                 std::chrono::duration_cast<std::chrono::milliseconds>(now - backoff_.lost_at())) +
             " and " + std::to_string(backoff_.tries()) + " tries; the last: " + lost_reason_);
        return;
    }
    // The last try is made when the time is up, not after it.
    const auto delay = std::min<net::Backoff::Clock::duration>(
        backoff_.next_delay(), backoff_.lost_at() + config_.reconnect.give_up_after - now);
    next_try_ = now + delay;
    waiting_ = true;
    notice("Reconnecting (try " + std::to_string(backoff_.tries()) + ", in " +
           seconds_text(std::chrono::duration_cast<std::chrono::milliseconds>(delay)) + ").");
}

void BotRunner::try_resume() {
    waiting_ = false;
    resuming_ = true;
    welcomed_ = false;
    start();
}

std::string BotRunner::seat_words() const {
    if (!room_) {
        return "the seat";
    }
    return (room_->you >= 0 ? "seat " + std::to_string(room_->you)
                            : std::string("the spectator's place")) +
           " in room " + room_->code;
}

void BotRunner::notice(const std::string& text) {
    if (on_notice) {
        on_notice(text);
    }
}

bool BotRunner::run_until_done(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!done()) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            fail("Timed out after " + std::to_string(timeout.count()) + " ms.");
            break;
        }
        step(std::min(left, std::chrono::milliseconds(100)));
    }
    return done();
}

void BotRunner::drop() {
    dropped_ = true;
    if (connection_) {
        connection_->close();
    }
}

void BotRunner::resume() {
    dropped_ = false;
    resuming_ = true;
    welcomed_ = false;
    start();
}

void BotRunner::fail(std::string why) {
    if (summary_.failure.empty() && !summary_.finished) {
        summary_.failure = std::move(why);
    }
}

void BotRunner::handle(const proto::ServerMessage& message) {
    std::visit(Overloaded{
                   [&](const proto::Welcome& m) { on_welcome(m); },
                   [&](const proto::RoomState& m) { on_room_state(m); },
                   [&](const proto::Snapshot& m) { on_snapshot(m); },
                   [&](const proto::Event& m) { on_event(m); },
                   [&](const proto::ShotResult& m) { on_shot_result(m); },
                   [&](const proto::Error& m) { on_error(m); },
                   [&](const proto::Pong&) {},
               },
               message);
}

void BotRunner::on_welcome(const proto::Welcome& welcome) {
    const bool same_token = welcome.resume_token == token_;
    token_ = welcome.resume_token;
    welcomed_ = true;
    if (resuming_ && !same_token) {
        fail("The server did not give the seat back on resume.");
        return;
    }
    if (!resuming_) {
        send_room_request();
    }
    // Resuming: the seat is back with the room's state, or gone with a bad_token error.
}

void BotRunner::send_room_request() {
    switch (config_.mode) {
    case JoinMode::Create:
        connection_->send(config_.create);
        break;
    case JoinMode::Join:
        connection_->send(proto::JoinRoom{config_.code, proto::Role::Player});
        break;
    case JoinMode::Spectate:
        connection_->send(proto::JoinRoom{config_.code, proto::Role::Spectator});
        break;
    case JoinMode::Quick:
        connection_->send(proto::QuickMatch{config_.quick_rule_set, config_.quick_seats});
        break;
    }
}

void BotRunner::on_room_state(const proto::RoomState& room) {
    const bool missed_game_end = resuming_ && room.phase == proto::Phase::GameOver && room_ &&
                                 room_->phase != proto::Phase::GameOver;
    if (resuming_) {
        resuming_ = false;
        ++summary_.resumes;
        if (reconnecting_) {
            notice("Resumed " + seat_words() + " (try " + std::to_string(backoff_.tries()) + ").");
        }
        reconnecting_ = false;
        last_played_turn_ = -1; // a shot sent into the lost connection is sent again if still due
        last_seq_ = -1;
        awaiting_keyframe_ = false;
    }
    room_ = room;
    summary_.room_code = room.code;
    summary_.seat = room.you;
    summary_.team =
        room.you >= 0 ? rules::team_of_seat(room.you, room.seats.size() == 4 ? 4 : 2) : -1;
    if (missed_game_end) { // the game ended while this bot was away: its game_end is gone
        on_game_end(proto::GameEndEvent{room.winner, "ended_while_away", room.scores});
        return;
    }
    maybe_play();
}

void BotRunner::on_snapshot(const proto::Snapshot& snapshot) {
    ++summary_.snapshots;
    if (snapshot.keyframe) {
        ++summary_.keyframes;
        awaiting_keyframe_ = false;
    } else if (last_seq_ >= 0 && snapshot.seq != last_seq_ + 1) {
        ++summary_.seq_gaps;
        awaiting_keyframe_ = true;
    }
    last_seq_ = snapshot.seq;
}

void BotRunner::on_event(const proto::Event& event) {
    if (const auto* turn = std::get_if<proto::TurnEvent>(&event)) {
        if (room_) {
            room_->turn = turn->turn;
            room_->to_play = turn->seat;
            room_->phase = proto::Phase::Aiming;
        }
        maybe_play();
    } else if (const auto* end = std::get_if<proto::GameEndEvent>(&event)) {
        on_game_end(*end);
    }
}

void BotRunner::on_shot_result(const proto::ShotResult& result) {
    if (awaiting_keyframe_) { // every shot ends with a keyframe, sent before its result
        ++summary_.unrepaired_gaps;
        awaiting_keyframe_ = false;
    }
    if (room_ && result.seat == room_->you) {
        ++summary_.shots;
        refusals_ = 0;
    }
}

void BotRunner::on_error(const proto::Error& error) {
    ++summary_.errors[error.code];
    if (error.code == proto::code::kBadToken && resuming_) {
        fail("The server no longer holds " + seat_words() + " (bad_token: " + error.message +
             "); the match is lost.");
        return;
    }
    if (is_fatal_error(error.code)) {
        fail("The server said " + error.code + ": " + error.message);
        return;
    }
    if (!is_game_input_error(error.code)) {
        return;
    }
    if (++refusals_ > config_.max_refusals) {
        fail("Too many refused shots in a row; the last: " + error.message);
        return;
    }
    strategy_.shot_refused();
    if (error.code == proto::code::kIllegalPlacement || error.code == proto::code::kIllegalShot) {
        last_played_turn_ = -1; // same board, same turn: choose again now
        maybe_play();
    }
}

void BotRunner::on_game_end(const proto::GameEndEvent& end) {
    ++summary_.games;
    summary_.scores = end.scores;
    summary_.last_reason = end.rule.empty() ? end.reason : end.rule; // the journal's name
    const int seat = room_ ? room_->you : -1;
    if (seat >= 0) {
        if (end.winner < 0) {
            ++summary_.draws;
        } else if (end.winner == summary_.team) { // the winning team's number
            ++summary_.wins;
        } else {
            ++summary_.losses;
        }
    }
    last_played_turn_ = -1;
    last_seq_ = -1;
    if (room_) {
        room_->phase = proto::Phase::GameOver;
    }
    const bool seat_lost = end.reason == "forfeit" || end.reason == "left";
    if (summary_.games < config_.games && !seat_lost) {
        if (seat >= 0) {
            connection_->send(proto::Rematch{});
        }
        return;
    }
    connection_->send(proto::Leave{});
    summary_.finished = true;
    connection_->close();
}

void BotRunner::maybe_play() {
    if (!room_ || done() || room_->you < 0 || room_->phase != proto::Phase::Aiming ||
        room_->to_play != room_->you || room_->turn == last_played_turn_) {
        return;
    }
    const rules::MatchState state = match_state_from(*room_);
    const Shot shot = strategy_.choose_shot(state, room_->you, config_.budget);
    last_played_turn_ = room_->turn;
    if (config_.send_aim) {
        connection_->send(proto::Aim{room_->turn, shot.x_px});
    }
    const proto::Shoot shoot{room_->turn, shot.x_px, shot.angle_rad, shot.power};
    connection_->send(shoot);
    if (on_shoot) {
        on_shoot(shoot);
    }
}

} // namespace carrom::bots
