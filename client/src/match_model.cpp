#include "carrom/client/match_model.hpp"

#include "carrom/client/plain_words.hpp"
#include "carrom/overloaded.hpp"
#include "carrom/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <utility>

namespace carrom::client {
namespace {

std::vector<std::string> names_of(const std::vector<SeatView>& seats) {
    std::vector<std::string> out;
    for (const SeatView& s : seats) {
        out.push_back(s.occupied ? s.name : std::string());
    }
    return out;
}

} // namespace

MatchModel::MatchModel(const PhysicsConfig& physics, const PlayoutConfig& playout,
                       const InterpolationConfig& interpolation)
    : physics_(physics), playout_config_(playout), interpolation_config_(interpolation),
      playout_(playout), buffer_(make_board_geometry(physics), interpolation),
      prediction_(physics) {
    for (const Body& b : standard_layout(physics)) {
        kinds_[b.id] = b.kind;
    }
    kinds_[kStrikerId] = BodyKind::Striker;
}

void MatchModel::reset() {
    view_ = {};
    emotes_.clear();
    playout_ = PlayoutClock(playout_config_);
    buffer_ = InterpolationBuffer(make_board_geometry(physics_), interpolation_config_);
    coins_ = {};
    sounds_.clear();
    timeline_.clear();
    due_said_.reset();
    last_proto_seq_.reset();
    prediction_.drop();
}

void MatchModel::apply_motion(const proto::MotionInfo& motion) {
    // A server that sends a delta at every change of motion makes the free motion past the
    // newest state exact: the delay only covers the jitter, and the board may be drawn further
    // ahead of the newest state (docs/interpolation.md, "The render time").
    playout_.set_interval_factor(motion.contact_snapshots ? 0.0 : playout_config_.interval_factor);
    buffer_.set_motion(motion.damping_per_s, motion.contact_snapshots);
}

void MatchModel::handle(const proto::ServerMessage& message, double local_s) {
    std::visit(Overloaded{
                   [&](const proto::Welcome& m) {
                       server_clock_.one_way(m.server_time_ms, local_s);
                       drop_unconfirmed_prediction(); // a new connection: the shot may be lost
                   },
                   [&](const proto::RoomState& m) { on_room_state(m, local_s); },
                   [&](const proto::Snapshot& m) { on_snapshot(m, local_s); },
                   [&](const proto::Event& m) { on_event(m, local_s); },
                   [&](const proto::ShotResult& m) { on_shot_result(m, local_s); },
                   [&](const proto::Error& m) { on_error(m, local_s); },
                   [&](const proto::Pong&) {},     // the session measures round trips
                   [&](const proto::Redirect&) {}, // the session follows it
               },
               message);
}

bool MatchModel::my_turn() const {
    return view_.in_room && view_.you >= 0 && view_.phase == proto::Phase::Aiming &&
           view_.to_play == view_.you;
}

rules::Side MatchModel::view_side() const {
    return view_.you >= 0 ? seat_side(view_.you) : rules::Side::Bottom;
}

std::optional<double> MatchModel::shot_clock_left_s(double local_s) const {
    if (!view_.deadline_ms || view_.phase != proto::Phase::Aiming) {
        return std::nullopt;
    }
    return seconds_until(server_clock_, *view_.deadline_ms, local_s);
}

std::optional<int> MatchModel::countdown_tick(double local_s) {
    const auto left = shot_clock_left_s(local_s);
    if (!left || !my_turn() || *left <= 0.0 || *left > kCountdownS) {
        return std::nullopt;
    }
    const std::pair<int, int> tick{view_.turn, static_cast<int>(std::ceil(*left))};
    if (last_tick_ == tick) {
        return std::nullopt;
    }
    last_tick_ = tick;
    return tick.second;
}

bool MatchModel::board_summary_shown(double local_s) const {
    return view_.board_summary && view_.phase != proto::Phase::GameOver &&
           local_s < view_.board_summary->shown_at_s + kBoardSummaryS;
}

std::string MatchModel::seat_name(int seat) const {
    return client::seat_name(view_, seat);
}

std::optional<SeatCoins> MatchModel::coins_left(int seat) const {
    if (seat < 0 || static_cast<std::size_t>(seat) >= view_.seats.size()) {
        return std::nullopt;
    }
    return seat_coins(coins_, view_.rule_set, view_.seats[static_cast<std::size_t>(seat)].colour);
}

BodyKind MatchModel::kind_of(int id) const {
    const auto it = kinds_.find(id);
    return it != kinds_.end() ? it->second : BodyKind::Black;
}

double MatchModel::continuous_now(double local_s) const {
    const double now = local_s - playout_.base_transit_s();
    return buffer_.empty() ? now : std::max(now, buffer_.newest_time() + 1e-3);
}

void MatchModel::on_room_state(const proto::RoomState& m, double local_s) {
    if (view_.in_room && m.code != view_.code) {
        reset();
    }
    const bool joined = !view_.in_room;
    server_clock_.one_way(m.server_time_ms, local_s);
    view_.in_room = true;
    view_.code = m.code;
    view_.you = m.you;
    view_.rule_set = m.rule_set;
    view_.options = m.options;
    view_.aim_assist = m.aim_assist;
    view_.spectators = m.spectators;
    view_.board_number = m.board_number;
    view_.turn = m.turn;
    view_.to_play = m.to_play;
    view_.phase = m.phase;
    view_.queen = m.queen;
    view_.winner = m.winner;
    view_.deadline_ms = m.shot_clock_deadline_ms;
    apply_motion(m.motion);
    if (prediction_.active() && m.turn != prediction_.turn()) {
        // The predicted stroke is over (its last keyframe may have been lost with a connection
        // that a resume replaced): end the prediction once its blends are done.
        if (prediction_.confirmed()) {
            prediction_.mark_server_done();
        } else {
            drop_unconfirmed_prediction();
        }
    }
    const bool over_on_arrival = m.phase == proto::Phase::GameOver && !view_.result;
    if (m.phase != proto::Phase::GameOver) {
        view_.result.reset(); // a new game (a rematch)
    }
    view_.seats.resize(m.seats.size());
    for (std::size_t i = 0; i < m.seats.size(); ++i) {
        SeatView& s = view_.seats[i];
        const proto::SeatInfo& in = m.seats[i];
        s = {in.occupied, in.name, in.connected, in.bot, in.colour, in.baseline, 0, 0};
        s.score = i < m.scores.size() ? m.scores[i] : 0;
        s.dues = i < m.dues.size() ? m.dues[i] : 0;
    }
    if (over_on_arrival) {
        view_.result = GameResult{m.winner, "", m.scores, names_of(view_.seats)};
    }
    Snapshot keyframe;
    keyframe.seq = next_seq_++;
    keyframe.time_s = continuous_now(local_s);
    keyframe.keyframe = true;
    for (const proto::BoardBody& b : m.bodies) {
        kinds_[b.id] = b.kind;
        keyframe.bodies.push_back({b.id, b.kind, b.pos_px, b.vel_px_s, b.pocketed});
    }
    buffer_.push(keyframe);
    if (joined) {
        say(m.you >= 0 ? "Joined room " + m.code : "Watching room " + m.code, Tone::Info, local_s);
    }
}

void MatchModel::on_snapshot(const proto::Snapshot& m, double local_s) {
    if (last_proto_seq_ && m.seq <= *last_proto_seq_ && !m.keyframe) {
        return; // duplicate or reordered
    }
    last_proto_seq_ = m.seq;
    if (!m.keyframe) {
        view_.phase = proto::Phase::Moving;
    }
    // A keyframe at t = 0 is the board at rest (a join, a resume or a new game before the turn's
    // shot): the shot's own t = 0 comes later, when it is played, so it fixes no offset.
    const bool at_rest = m.keyframe && m.t_s <= 0.0;
    double offset = at_rest ? continuous_now(local_s) : 0.0;
    if (!at_rest) {
        if (const auto start = timeline_.start_of(m.turn)) {
            offset = *start;
        } else {
            offset = continuous_now(local_s) - m.t_s;
            timeline_.place(m.turn, offset);
            sounds_.start(m.turn, offset);
        }
    }
    const std::vector<BodyState> before = board_now();
    auto previous_pos = [&](int id) {
        const auto it = std::find_if(before.begin(), before.end(),
                                     [id](const BodyState& b) { return b.id == id; });
        return it != before.end() ? it->pos_px : Vec2{};
    };
    Snapshot s;
    s.seq = next_seq_++;
    s.time_s = offset + m.t_s;
    s.keyframe = m.keyframe;
    for (const proto::SnapshotBody& b : m.bodies) {
        s.bodies.push_back({b.id, kind_of(b.id), b.pos_px, b.vel_px_s, false});
    }
    for (int id : m.pocketed) {
        s.bodies.push_back({id, kind_of(id), previous_pos(id), {}, true});
    }
    const bool predicted = prediction_.active() && m.turn == prediction_.turn() && !at_rest;
    if (!buffer_.push(s)) {
        return;
    }
    if (predicted) {
        // Placed on the prediction's timeline, which runs ahead of the server's stream by the
        // round trip: not a measure of the network for the playout clock. The stroke's last
        // keyframe is the board after the rules (the striker on the next baseline, returned
        // pieces placed): no physics to compare, the hand-over to it is a blend.
        if (m.keyframe) {
            prediction_.mark_server_done();
        } else {
            // Compared at the server's own shot time: offset + t - offset is not always t in
            // floating point, and a hair before a pocketing the body is still on the board.
            prediction_.confirm(*buffer_.newest_state(), m.t_s, local_s);
        }
    } else {
        playout_.on_snapshot(s.time_s, local_s);
    }
}

bool MatchModel::predict(const proto::Shoot& shot, double local_s) {
    if (!my_turn() || shot.turn != view_.turn || prediction_.active() || buffer_.empty()) {
        return false;
    }
    std::vector<BodyState> board = board_now();
    const bool at_rest = std::all_of(board.begin(), board.end(), [](const BodyState& b) {
        return b.pocketed || b.vel_px_s == Vec2{};
    });
    if (!at_rest) {
        return false;
    }
    // The stroke starts at the time drawn now, so the next frame shows it moving. The board at
    // rest is placed again just before it (the newest state may lie ahead of the drawn time by
    // the playout delay), so that the server's snapshots of the stroke follow it in the buffer.
    const double start = playout_.render_time(local_s);
    if (!prediction_.start(view_.turn, board, seat_side(view_.you),
                           Shot{shot.x_px, shot.angle_rad, shot.power}, start)) {
        return false;
    }
    buffer_.clear();
    Snapshot rest;
    rest.seq = next_seq_++;
    rest.time_s = start - 1e-3;
    rest.keyframe = true;
    rest.bodies = std::move(board);
    buffer_.push(rest);
    timeline_.place(view_.turn, start);
    sounds_.set_predicted(prediction_.cues());
    view_.phase = proto::Phase::Moving;
    return true;
}

void MatchModel::cue(int turn, double t_s, SoundKind kind, double volume) {
    if (volume <= 0.0) {
        return;
    }
    if (prediction_.claim_cue(turn, kind, t_s)) {
        return; // predicted, and played already
    }
    sounds_.add(turn, t_s, kind, volume, timeline_.start_of(turn));
}

void MatchModel::on_event(const proto::Event& m, double local_s) {
    std::visit(
        Overloaded{
            [&](const proto::CollisionEvent& e) {
                cue(e.turn, e.t_s, SoundKind::Click, loudness_from_impulse(e.impulse));
            },
            [&](const proto::CushionEvent& e) {
                cue(e.turn, e.t_s, SoundKind::Cushion, 0.8 * loudness_from_impulse(e.impulse));
            },
            [&](const proto::PocketEvent& e) { cue(e.turn, e.t_s, SoundKind::Pocket, 1.0); },
            [&](const proto::FoulEvent&) {}, // said with its stroke's shot_result
            [&](const proto::QueenEvent& e) {
                view_.queen = e.queen;
                say(queen_sentence(e.queen, seat_name(e.queen.seat)), Tone::Info, local_s);
            },
            [&](const proto::DueEvent& e) { on_due(e, local_s); },
            [&](const proto::TurnEvent& e) {
                server_clock_.one_way(e.server_time_ms, local_s);
                view_.turn = e.turn;
                view_.to_play = e.seat;
                view_.deadline_ms = e.deadline_ms;
                view_.phase = proto::Phase::Aiming;
                view_.aim_x_px.reset();
                // Not said: the status line names the seat to play ("Your turn").
            },
            [&](const proto::BoardEndEvent& e) { on_board_end(e, local_s); },
            [&](const proto::GameEndEvent& e) {
                for (std::size_t i = 0; i < e.scores.size() && i < view_.seats.size(); ++i) {
                    view_.seats[i].score = e.scores[i];
                }
                view_.winner = e.winner;
                view_.phase = proto::Phase::GameOver;
                view_.board_summary.reset(); // the game-over panel says it
                view_.result =
                    GameResult{e.winner, e.reason, e.scores, names_of(view_.seats), e.rule};
                on_forfeit_end(e, local_s);
            },
            [&](const proto::PlayerDroppedEvent& e) {
                if (e.seat >= 0 && static_cast<std::size_t>(e.seat) < view_.seats.size()) {
                    view_.seats[static_cast<std::size_t>(e.seat)].connected = false;
                }
                const auto grace_s = (e.grace_deadline_ms - e.server_time_ms) / 1000;
                say(seat_name(e.seat) + " lost the connection; they have " +
                        std::to_string(grace_s) + " s to come back",
                    Tone::Error, local_s);
            },
            [&](const proto::PlayerReturnedEvent& e) {
                if (e.seat >= 0 && static_cast<std::size_t>(e.seat) < view_.seats.size()) {
                    view_.seats[static_cast<std::size_t>(e.seat)].connected = true;
                }
                say(seat_name(e.seat) + " is back", Tone::Info, local_s);
            },
            [&](const proto::AimEvent& e) {
                if (e.seat != view_.you && e.turn == view_.turn) {
                    view_.aim_x_px = e.x_px;
                }
            },
            [&](const proto::EmoteEvent& e) { emotes_.receive(e.seat, e.emote, local_s); },
            [&](const proto::PausedEvent& e) { say(e.message, Tone::Error, local_s); },
            [&](const proto::ResumedEvent&) { say("The match goes on", Tone::Info, local_s); },
        },
        m);
}

// Dues are the team's: partners owe them together. The server sends one `due` per seat of the
// team; the HUD says it once per team.
void MatchModel::on_due(const proto::DueEvent& e, double local_s) {
    const int team = team_of(view_, e.seat);
    for (const int seat : team_seats(view_, team)) {
        view_.seats[static_cast<std::size_t>(seat)].dues = e.owed;
    }
    const bool said = due_said_ && due_said_->team == team && due_said_->owed == e.owed;
    due_said_ = DueSaid{team, e.owed};
    if (said || e.owed <= 0) {
        return;
    }
    say(dues_sentence(team_subject(view_, team), view_.seats.size() == 4, e.owed), Tone::Foul,
        local_s);
}

// "Asha left the match: Ravi wins by forfeit", from the reader's side: good news for the
// winners, a warning for the losers.
void MatchModel::on_forfeit_end(const proto::GameEndEvent& e, double local_s) {
    const int leaver = std::exchange(forfeit_seat_, -1);
    if ((e.reason != "left" && e.reason != "forfeit") || leaver < 0 || e.winner < 0) {
        return;
    }
    const bool doubles = view_.seats.size() == 4;
    const bool ours = view_.you >= 0 && team_of(view_, view_.you) == e.winner;
    const std::string winner =
        ours ? (doubles ? "your team" : "you") : team_subject(view_, e.winner);
    say(forfeit_sentence(seat_name(leaver), e.reason, winner, doubles ? !ours : ours),
        ours ? Tone::Good : (view_.you >= 0 ? Tone::Foul : Tone::Info), local_s);
}

// The board's winner is a team (its first seat): in doubles both partners are named.
void MatchModel::on_board_end(const proto::BoardEndEvent& e, double local_s) {
    for (std::size_t i = 0; i < e.scores.size() && i < view_.seats.size(); ++i) {
        view_.seats[i].score = e.scores[i];
    }
    view_.phase = proto::Phase::BoardOver;
    view_.board_summary = BoardSummary{e.board, e.winner, e.points, local_s};
    const std::string board = "Board " + std::to_string(e.board);
    // Freestyle scores each stroke: its board_end adds no points, so none are named.
    const std::string points = e.points > 0 ? " (+" + std::to_string(e.points) + ")" : "";
    say(e.winner >= 0 ? board + " to " + team_subject(view_, e.winner) + points
                      : board + " ends, no winner",
        Tone::Good, local_s);
}

void MatchModel::on_shot_result(const proto::ShotResult& m, double local_s) {
    due_said_.reset(); // the stroke's rule events (`due` among them) follow its shot_result
    for (std::size_t i = 0; i < view_.seats.size(); ++i) {
        if (i < m.scores.size()) {
            view_.seats[i].score = m.scores[i];
        }
        if (i < m.dues.size()) {
            view_.seats[i].dues = m.dues[i];
        }
    }
    view_.queen = m.queen;
    view_.turn = m.next_turn;
    view_.to_play = m.next_seat;
    std::vector<BodyKind> kinds;
    for (int id : m.pocketed) {
        kinds.push_back(kind_of(id));
    }
    const auto seat = static_cast<std::size_t>(m.seat);
    const int points = seat < m.points.size() ? m.points[seat] : 0;
    const bool fouled = !m.fouls.empty();
    const std::string name = seat_name(m.seat);
    if (!kinds.empty()) {
        say(name + " pocketed " + pocket_list(kinds) + stroke_points(points),
            fouled ? Tone::Foul : Tone::Good, local_s);
    }
    for (const proto::Foul& foul : m.fouls) {
        if (foul.rule == "forfeit") {
            forfeit_seat_ = m.seat; // said with game_end, which gives the reason
        } else {
            say(foul_sentence(name, foul.message), Tone::Foul, local_s);
        }
    }
    std::vector<BodyKind> returned;
    for (int id : m.returned) {
        returned.push_back(kind_of(id));
    }
    const std::string cost = fouled ? foul_cost(returned, points) : std::string();
    if (!cost.empty()) {
        say(cost, Tone::Foul, local_s);
    }
    if (m.extra_turn && !m.game_over && !m.board_over) {
        say(seat_name(m.seat) + " plays again", Tone::Info, local_s);
    }
}

void MatchModel::drop_unconfirmed_prediction() {
    if (!prediction_.active() || prediction_.confirmed()) {
        return;
    }
    // Back to the board at rest.
    timeline_.forget(prediction_.turn());
    prediction_.drop();
    sounds_.drop_predicted();
    if (view_.phase == proto::Phase::Moving) {
        view_.phase = proto::Phase::Aiming;
    }
}

void MatchModel::say(std::string text, Tone tone, double local_s) {
    transcript_.push_back(HudLine{text, tone, local_s});
    if (transcript_.size() > kTranscriptLines) {
        transcript_.pop_front();
    }
    log_.post(std::move(text), tone, local_s);
}

void MatchModel::on_error(const proto::Error& m, double local_s) {
    drop_unconfirmed_prediction(); // the shot was refused
    say(error_sentence(m), Tone::Error, local_s);
}

std::vector<RenderedBody> MatchModel::render(double local_s) {
    const double t = playout_.render_time(local_s);
    last_render_s_ = t;
    std::vector<RenderedBody> bodies =
        prediction_.active() ? render_predicted(t, local_s) : buffer_.sample(t);
    coins_ = count_coins(bodies);
    sounds_.render_to(t);
    // While aiming, the striker is drawn where the shooter places it, not where it last stopped.
    if (view_.phase == proto::Phase::Aiming && !animating()) {
        std::erase_if(bodies, [](const RenderedBody& b) { return b.kind == BodyKind::Striker; });
    }
    return bodies;
}

std::vector<RenderedBody> MatchModel::render_predicted(double t_s, double local_s) {
    // The server's states reach the drawn time, or its stroke is over.
    const bool server_reaches =
        prediction_.confirmed() &&
        (prediction_.server_done() || (!buffer_.empty() && buffer_.newest_time() >= t_s));
    if (!server_reaches) {
        return prediction_.draw(t_s, local_s, nullptr);
    }
    std::vector<RenderedBody> server = buffer_.sample(t_s);
    if (prediction_.server_done() && !prediction_.blending(local_s)) {
        // The server's last state of the stroke is drawn: the prediction is over.
        prediction_.stop();
        const PredictionStats& stats = prediction_.stats();
        if (stats.corrections > corrections_logged_) {
            char largest[32];
            std::snprintf(largest, sizeof largest, "%.2f", stats.stroke_max_difference_px);
            say("The server corrected the predicted shot: " +
                    count_words(stats.corrections - corrections_logged_, "piece", "pieces") +
                    " moved, by up to " + largest + " px",
                Tone::Info, local_s);
            corrections_logged_ = stats.corrections;
        }
        return server;
    }
    return prediction_.draw(t_s, local_s, &server);
}

std::vector<SoundCue> MatchModel::take_sounds() {
    return sounds_.take();
}

bool MatchModel::animating() const {
    return view_.phase == proto::Phase::Moving || prediction_.active() ||
           (!buffer_.empty() && last_render_s_ < buffer_.newest_time());
}

std::vector<BodyState> MatchModel::board_now() const {
    const std::vector<BodyState>* s = buffer_.newest_state();
    return s != nullptr ? *s : std::vector<BodyState>{};
}

} // namespace carrom::client
