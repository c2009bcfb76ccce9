#include "carrom/client/demo_link.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace carrom::client {
namespace {

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

proto::QueenInfo queen_info(const rules::QueenState& q) {
    switch (q.status) {
    case rules::QueenStatus::PendingCover:
        return {proto::QueenState::Pending, q.seat};
    case rules::QueenStatus::Covered:
        return {proto::QueenState::Covered, q.seat};
    case rules::QueenStatus::OutOfPlay:
        return {proto::QueenState::None, -1};
    case rules::QueenStatus::OnBoard:
        break;
    }
    return {proto::QueenState::OnBoard, -1};
}

proto::Phase phase_of(const rules::MatchState& m, bool moving) {
    if (moving) {
        return proto::Phase::Moving;
    }
    switch (m.phase) {
    case rules::Phase::AwaitingShot:
        return proto::Phase::Aiming;
    case rules::Phase::BoardOver:
        return proto::Phase::BoardOver;
    case rules::Phase::GameOver:
        return proto::Phase::GameOver;
    }
    return proto::Phase::Aiming;
}

std::string sentence_for(rules::RuleCode code) {
    std::string text(rules::to_string(code));
    std::replace(text.begin(), text.end(), '_', ' ');
    if (!text.empty()) {
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    }
    return text;
}

Baseline baseline_of(int seat) {
    return seat == 0 ? Baseline::Bottom : Baseline::Top;
}

} // namespace

DemoLink::DemoLink(const PhysicsConfig& physics, std::function<double()> clock,
                   const DemoConfig& config)
    : physics_(physics), clock_(std::move(clock)), config_(config), engine_(physics) {}

std::int64_t DemoLink::server_ms(double now_s) const {
    return static_cast<std::int64_t>(std::llround(now_s * 1000.0)) + config_.server_clock_offset_ms;
}

LinkStatus DemoLink::status() const {
    return open_ ? LinkStatus{LinkState::Open, "Offline demo"}
                 : LinkStatus{LinkState::Closed, "The demo ended"};
}

void DemoLink::close() {
    open_ = false;
}

void DemoLink::send(const proto::ClientMessage& message) {
    if (!open_) {
        return;
    }
    const double now = clock_();
    std::visit(Overloaded{
                   [&](const proto::Hello& h) {
                       player_name_ = h.name;
                       outbox_.push_back(proto::Welcome{proto::kProtocolVersion, 1,
                                                        "0123456789abcdef0123456789abcdef",
                                                        server_ms(now)});
                   },
                   [&](const proto::CreateRoom&) { open_room(now); },
                   [&](const proto::JoinRoom&) { open_room(now); },
                   [&](const proto::QuickMatch&) { open_room(now); },
                   [&](const proto::Aim&) {},
                   [&](const proto::Shoot& s) {
                       if (!in_room_ || streaming_ || match_.phase != rules::Phase::AwaitingShot) {
                           outbox_.push_back(proto::Error{std::string(proto::code::kInMotion),
                                                          "Wait until the pieces stop."});
                       } else if (match_.turn_seat != 0) {
                           outbox_.push_back(proto::Error{std::string(proto::code::kNotYourTurn),
                                                          "It is not your turn."});
                       } else if (s.turn != match_.turn_number) {
                           outbox_.push_back(proto::Error{std::string(proto::code::kStaleTurn),
                                                          "That shot was for another turn."});
                       } else {
                           start_shot(0, Shot{s.x_px, s.angle_rad, s.power}, now);
                       }
                   },
                   [&](const proto::Rematch&) {
                       if (match_.phase == rules::Phase::GameOver) {
                           open_room(now);
                       }
                   },
                   [&](const proto::Leave&) { open_ = false; },
                   [&](const proto::Ping& p) {
                       outbox_.push_back(proto::Pong{p.nonce, server_ms(now)});
                   },
               },
               message);
}

std::vector<proto::ServerMessage> DemoLink::poll() {
    if (open_) {
        advance(clock_());
    }
    std::vector<proto::ServerMessage> out(outbox_.begin(), outbox_.end());
    outbox_.clear();
    return out;
}

void DemoLink::open_room(double now_s) {
    rules::RulesConfig rules;
    rules.first_breaker = 1;
    rules.shot_clock_s = config_.shot_clock_s;
    match_ = rules::new_match(rules::RuleSet::Icf, rules, physics_);
    in_room_ = true;
    streaming_.reset();
    turn_started_s_ = now_s;
    outbox_.push_back(room_state(now_s));
    outbox_.push_back(proto::Event{turn_event(now_s)});
}

proto::RoomState DemoLink::room_state(double now_s) const {
    proto::RoomState r;
    r.code = "DEMXYZ"; // a valid room code (no 0, O, 1, I, L)
    r.you = 0;
    r.rule_set = proto::RuleSet::Icf;
    r.options = {match_.config.target_points, match_.config.max_boards, config_.shot_clock_s};
    for (int seat = 0; seat < 2; ++seat) {
        proto::SeatInfo s;
        s.occupied = true;
        s.name = seat == 0 ? player_name_ : "Demo bot";
        s.connected = true;
        s.bot = seat == 1;
        const auto colour = rules::team_colour(match_, seat);
        s.colour = !colour                      ? proto::Colour::None
                   : *colour == BodyKind::White ? proto::Colour::White
                                                : proto::Colour::Black;
        s.baseline = baseline_of(seat);
        r.seats.push_back(s);
    }
    r.scores = match_.scores;
    r.dues = match_.dues_owed;
    r.board_number = match_.board;
    r.turn = match_.turn_number;
    r.to_play = match_.turn_seat;
    if (config_.shot_clock_s > 0.0) {
        r.shot_clock_deadline_ms = server_ms(turn_started_s_ + config_.shot_clock_s);
    }
    r.server_time_ms = server_ms(now_s);
    r.phase = phase_of(match_, streaming_.has_value());
    r.queen = queen_info(match_.queen);
    r.winner = match_.result && match_.result->winner_team ? *match_.result->winner_team : -1;
    for (const Body& b : match_.bodies) {
        r.bodies.push_back(proto::to_board_body(b));
    }
    return r;
}

proto::TurnEvent DemoLink::turn_event(double now_s) const {
    proto::TurnEvent e;
    e.turn = match_.turn_number;
    e.seat = match_.turn_seat;
    if (config_.shot_clock_s > 0.0) {
        e.deadline_ms = server_ms(turn_started_s_ + config_.shot_clock_s);
    }
    e.server_time_ms = server_ms(now_s);
    return e;
}

Shot DemoLink::demo_shot(int seat) const {
    const Baseline side = baseline_of(seat);
    const double by = baseline_y(physics_, side);
    if (match_.strokes_this_board == 0) {
        const double down = side == Baseline::Top ? 1.0 : -1.0;
        return {physics_.centre().x, down * std::numbers::pi / 2.0, physics_.max_power};
    }
    // Aim straight at the first coin on the board, from a free spot on the baseline.
    const auto colour = rules::team_colour(match_, seat);
    Vec2 target = physics_.centre();
    for (const Body& b : match_.bodies) {
        if (!b.pocketed && (!colour || b.kind == *colour)) {
            target = b.pos_px;
            break;
        }
    }
    const double lo = baseline_x_min(physics_);
    const double hi = baseline_x_max(physics_);
    double x = std::clamp(target.x, lo, hi);
    for (int step = 0; step < 20; ++step) {
        const Vec2 s{x, by};
        const bool free =
            std::none_of(match_.bodies.begin(), match_.bodies.end(), [&](const Body& b) {
                const double d = physics_.striker_radius_px + physics_.coin_radius_px;
                return !b.pocketed && length_squared(b.pos_px - s) < d * d;
            });
        if (free) {
            break;
        }
        x = x + 40.0 > hi ? lo + std::fmod(x + 40.0 - lo, hi - lo) : x + 40.0;
    }
    return {x, std::atan2(target.y - by, target.x - x), 0.6 * physics_.max_power};
}

void DemoLink::advance(double now_s) {
    if (!in_room_) {
        return;
    }
    if (streaming_) {
        stream(now_s);
        return;
    }
    if (match_.phase == rules::Phase::BoardOver) {
        match_ = rules::start_next_board(match_);
        turn_started_s_ = now_s;
        outbox_.push_back(room_state(now_s));
        outbox_.push_back(proto::Event{turn_event(now_s)});
        return;
    }
    if (match_.phase != rules::Phase::AwaitingShot) {
        return;
    }
    const double waited = now_s - turn_started_s_;
    if (match_.turn_seat != 0) {
        const double wait =
            match_.turn_number == 0 ? config_.first_shot_at_s : config_.opponent_think_s;
        if (waited >= wait) {
            start_shot(match_.turn_seat, demo_shot(match_.turn_seat), now_s);
        }
    } else if (config_.autoplay_after_s >= 0.0 && waited >= config_.autoplay_after_s) {
        start_shot(0, demo_shot(0), now_s);
    }
}

void DemoLink::start_shot(int seat, const Shot& shot, double now_s) {
    rules::PlayOptions options;
    options.record_trajectory = true;
    rules::PlayResult play = rules::play_shot(match_, seat, shot, engine_, options);
    if (play.error) {
        outbox_.push_back(
            proto::Error{std::string(proto::code::kIllegalPlacement), play.error->message});
        return;
    }
    Streaming s;
    s.start_s = now_s;
    s.turn = match_.turn_number;
    s.last_sent = play.outcome.physics.trajectory.initial;
    s.play = std::move(play);
    streaming_ = std::move(s);
    stream(now_s);
}

void DemoLink::stream(double now_s) {
    Streaming& s = *streaming_;
    const SimResult& sim = s.play.outcome.physics;
    const double elapsed = now_s - s.start_s;
    for (;;) {
        const double t = static_cast<double>(s.next_frame) / config_.snapshot_hz;
        if (t > elapsed || t >= sim.end_time_s) {
            break;
        }
        for (; s.next_event < sim.events.size() && sim.events[s.next_event].t_s <= t;
             ++s.next_event) {
            const Event& e = sim.events[s.next_event];
            if (e.kind == EventKind::Collision) {
                outbox_.push_back(
                    proto::Event{proto::CollisionEvent{s.turn, e.t_s, e.a, e.b, e.impulse}});
            } else if (e.kind == EventKind::Cushion) {
                outbox_.push_back(
                    proto::Event{proto::CushionEvent{s.turn, e.t_s, e.a, e.b, e.impulse}});
            } else if (e.kind == EventKind::Pocket) {
                outbox_.push_back(proto::Event{proto::PocketEvent{s.turn, e.t_s, e.a, e.b}});
            }
        }
        const std::vector<Body> now = state_at(physics_, sim.trajectory, t);
        proto::Snapshot snap;
        snap.seq = ++seq_;
        snap.turn = s.turn;
        snap.t_s = t;
        for (std::size_t i = 0; i < now.size(); ++i) {
            const Body& b = now[i];
            const Body& before = s.last_sent[i];
            if (b.pocketed && !before.pocketed) {
                snap.pocketed.push_back(b.id);
            } else if (!b.pocketed && (b.pos_px != before.pos_px || b.vel_px_s != before.vel_px_s ||
                                       s.next_frame == 0)) {
                snap.bodies.push_back(
                    {b.id,
                     {proto::quantise(b.pos_px.x), proto::quantise(b.pos_px.y)},
                     {proto::quantise(b.vel_px_s.x), proto::quantise(b.vel_px_s.y)}});
            }
        }
        s.last_sent = now;
        outbox_.push_back(std::move(snap));
        ++s.next_frame;
    }
    if (elapsed >= sim.end_time_s) {
        finish_shot(now_s);
    }
}

void DemoLink::finish_shot(double now_s) {
    Streaming s = std::move(*streaming_);
    streaming_.reset();
    const SimResult& sim = s.play.outcome.physics;
    proto::Snapshot key;
    key.seq = ++seq_;
    key.turn = s.turn;
    key.t_s = sim.end_time_s;
    key.keyframe = true;
    for (const Body& b : sim.bodies) {
        if (b.pocketed) {
            key.pocketed.push_back(b.id);
        } else {
            key.bodies.push_back({b.id, b.pos_px, {}});
        }
    }
    outbox_.push_back(std::move(key));
    const rules::ShotOutcome& o = s.play.outcome;
    const rules::QueenState queen_before = match_.queen;
    const std::vector<int> dues_before = match_.dues_owed;
    match_ = s.play.state;
    for (const rules::Foul& f : o.fouls) {
        outbox_.push_back(proto::Event{
            proto::FoulEvent{f.seat, std::string(rules::to_string(f.code)), sentence_for(f.code)}});
    }
    if (queen_info(queen_before) != queen_info(match_.queen)) {
        outbox_.push_back(proto::Event{proto::QueenEvent{queen_info(match_.queen)}});
    }
    for (std::size_t team = 0; team < match_.dues_owed.size(); ++team) {
        if (team >= dues_before.size() || dues_before[team] != match_.dues_owed[team]) {
            outbox_.push_back(
                proto::Event{proto::DueEvent{static_cast<int>(team), match_.dues_owed[team]}});
        }
    }
    proto::ShotResult r;
    r.turn = o.turn_number;
    r.seat = o.seat;
    r.x_px = o.shot.x_px;
    r.angle_rad = o.shot.angle_rad;
    r.power = o.shot.power;
    r.pocketed = o.pocketed;
    if (o.striker_pocketed) {
        r.pocketed.push_back(kStrikerId);
    }
    for (const rules::ReturnedPiece& p : o.returned) {
        r.returned.push_back(p.id);
    }
    for (const rules::Foul& f : o.fouls) {
        r.fouls.push_back({std::string(rules::to_string(f.code)), sentence_for(f.code)});
    }
    r.points = o.score_changes;
    r.scores = match_.scores;
    r.dues = match_.dues_owed;
    r.queen = queen_info(match_.queen);
    r.extra_turn = o.extra_stroke;
    r.next_turn = match_.turn_number;
    r.next_seat = match_.turn_seat;
    r.board_over = o.board_end.has_value();
    r.game_over = o.game_end.has_value();
    r.winner = o.game_end && o.game_end->winner_team ? *o.game_end->winner_team : -1;
    outbox_.push_back(r);
    turn_started_s_ = now_s;
    if (o.board_end) {
        outbox_.push_back(proto::Event{proto::BoardEndEvent{o.board_end->board,
                                                            o.board_end->winner_team.value_or(-1),
                                                            o.board_end->points, match_.scores}});
    }
    if (o.game_end) {
        outbox_.push_back(proto::Event{
            proto::GameEndEvent{o.game_end->winner_team.value_or(-1), "score", match_.scores}});
    } else if (match_.phase == rules::Phase::AwaitingShot) {
        outbox_.push_back(proto::Event{turn_event(now_s)});
    }
    outbox_.push_back(room_state(now_s));
}

} // namespace carrom::client
