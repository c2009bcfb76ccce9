#include "carrom/bots/bot_runner.hpp"

#include "carrom/bots/match_view.hpp"
#include "carrom/overloaded.hpp"
#include "carrom/rules/seat.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace carrom::bots {

namespace {

bool is_game_input_error(const std::string& code) {
    return code == proto::code::kIllegalPlacement || code == proto::code::kIllegalShot ||
           code == proto::code::kStaleTurn || code == proto::code::kNotYourTurn ||
           code == proto::code::kInMotion || code == proto::code::kWrongPhase;
}

// Seconds with one decimal, for sentences.
std::string seconds_text(double s) {
    const long tenths = std::lround(std::max(s, 0.0) * 10.0);
    return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10) + " s";
}

std::string said(const proto::Error& error) {
    return "The server said " + error.code + ": " + error.message;
}

} // namespace

BotRunner::BotRunner(BotConfig config, Strategy& strategy)
    : config_(std::move(config)), strategy_(strategy),
      core_(config_.reconnect,
            config_.auto_resume ? net::ReconnectPolicy::SeatOnly : net::ReconnectPolicy::Never,
            config_.url) {}

BotRunner::~BotRunner() = default;

double BotRunner::now_s() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

void BotRunner::start() {
    apply(core_.request());
    apply(core_.start(""));
}

void BotRunner::open_connection() {
    if (connection_) { // a redirect's: the server closes it (4005) once we go
        connection_->close();
    }
    BotConfig target = config_;
    target.url = core_.url(); // the given address, or where a redirect sends the bot
    connection_ = connect ? connect(target) : net::Connection::open(target.url, config_.connection);
    // The connection queues what is sent before it opens: hello goes out at once.
    apply(core_.link_opened());
}

void BotRunner::apply(const net::SessionActions& actions, const proto::Error* error) {
    using Kind = net::SessionActionKind;
    for (const net::SessionAction& action : actions) {
        switch (action.kind) {
        case Kind::Connect:
            open_connection();
            break;
        case Kind::SendHello:
        case Kind::SendResume:
            connection_->send(proto::Hello{
                proto::kProtocolVersion, config_.name,
                action.kind == Kind::SendResume ? std::optional(core_.token()) : std::nullopt,
                config_.identity, true});
            break;
        case Kind::SendJoin:
            connection_->send(proto::JoinRoom{core_.join_code(), core_.join_as()});
            break;
        case Kind::SendRoomRequest:
            send_room_request();
            break;
        case Kind::SendLeave:
            connection_->send(proto::Leave{});
            break;
        case Kind::Wait:
            if (core_.tries() == 1) {
                notice("Connection lost: " + lost_reason_ + " Resuming " + seat_words() +
                       " for up to " + seconds_text(config_.reconnect.give_up_after_s) + ".");
            }
            notice("Reconnecting (try " + std::to_string(core_.tries()) + ", in " +
                   seconds_text(action.wait_s) + ").");
            break;
        case Kind::Resumed: // on_room_state() counts it
            break;
        case Kind::SeatLost:
            fail(error ? "The server no longer holds " + seat_words() +
                             " (bad_token: " + error->message + "); the match is lost."
                       : std::string("The server did not give the seat back on resume."));
            break;
        case Kind::Refused:
            fail(error ? said(*error) : lost_reason_);
            break;
        case Kind::GiveUp:
            if (action.reason == net::GiveUpReason::RedirectRefused) {
                fail(core_.refused_redirect());
            } else if (action.reason == net::GiveUpReason::TimeUp) {
                fail("Gave up resuming " + seat_words() + " after " +
                     seconds_text(now_s() - core_.lost_since_s()) + " and " +
                     std::to_string(core_.tries()) + " tries; the last: " + lost_reason_);
            } else {
                fail(error ? said(*error) : lost_reason_);
            }
            break;
        }
    }
}

bool BotRunner::step(std::chrono::milliseconds wait) {
    if (!connection_ || done()) {
        return done();
    }
    if (!core_.link_up()) { // waiting for the next try
        const double left_s = core_.retry_at_s() - now_s();
        if (left_s > 0.0) {
            std::this_thread::sleep_for(std::min<std::chrono::duration<double>>(
                std::chrono::duration<double>(left_s), wait));
            return done();
        }
        apply(core_.tick(now_s()));
        return done();
    }
    connection_->wait(wait);
    // The status first: a link seen closed has every message it received in the inbox (a
    // redirect and the close 4005 after it can land between a poll and a later status).
    const auto status = connection_->status();
    const net::Connection* polled = connection_.get();
    for (const auto& message : connection_->poll()) {
        if (on_message) {
            on_message(message);
        }
        handle(message);
        if (done() || connection_.get() != polled) { // a redirect: the rest is the old link's
            break;
        }
    }
    summary_.decode_errors = connection_->decode_errors();
    if (!done() && !dropped_ && connection_.get() == polled &&
        status.state == net::ConnectionState::Closed) {
        connection_lost(status);
    }
    return done();
}

void BotRunner::connection_lost(const net::ConnectionStatus& status) {
    lost_reason_ = status.detail;
    apply(core_.link_closed(now_s(), status.close_code,
                            std::uniform_real_distribution<double>(0.0, 1.0)(jitter_)));
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
    apply(core_.start(core_.token()));
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
                   [&](const proto::Redirect& m) { on_redirect(m); },
               },
               message);
}

void BotRunner::on_welcome(const proto::Welcome& welcome) {
    // Resuming: the seat comes back with the room's state, or is gone with a bad_token error.
    apply(core_.welcome(welcome.resume_token));
}

void BotRunner::on_redirect(const proto::Redirect& redirect) {
    const net::SessionActions actions = core_.redirect(redirect);
    if (!actions.empty() && actions.front().kind == net::SessionActionKind::Connect) {
        ++summary_.redirects;
        notice("Redirected (" + redirect.reason + ") to " + redirect.url + ".");
    }
    apply(actions);
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
    const int tries = core_.tries(); // 0 after resume(): no reconnect of its own
    const net::SessionActions actions = core_.room_state();
    const bool resumed = std::find_if(actions.begin(), actions.end(), [](const auto& a) {
                             return a.kind == net::SessionActionKind::Resumed;
                         }) != actions.end();
    const bool missed_game_end = resumed && room.phase == proto::Phase::GameOver && room_ &&
                                 room_->phase != proto::Phase::GameOver;
    if (resumed) {
        ++summary_.resumes;
        if (tries > 0) {
            notice("Resumed " + seat_words() + " (try " + std::to_string(tries) + ").");
        }
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
    apply(core_.error(error.code), &error);
    if (done()) {
        return;
    }
    if (error.code == proto::code::kSpectator) { // this bot cannot get where it was going
        fail(said(error));
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
    apply(core_.leave());
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
