#include "carrom/client/replay_model.hpp"

#include "carrom/client/stream_quantise.hpp"

#include "carrom/exact_engine.hpp"
#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "carrom/room/outcome_messages.hpp"
#include "carrom/rules/placement.hpp"
#include "carrom/rules/state_hash.hpp"
#include "carrom/trajectory.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace carrom::client {

namespace {

proto::RuleSet wire_rule_set(rules::RuleSet value) {
    for (const proto::RuleSet r : {proto::RuleSet::Icf, proto::RuleSet::Seed,
                                   proto::RuleSet::Freestyle, proto::RuleSet::DiscPool}) {
        if (proto::to_rules(r) == value) {
            return r;
        }
    }
    return proto::RuleSet::Icf;
}

// The board as the room shows it between strokes: the pieces, and the striker of the seat to
// move on its baseline at the centre (where a new turn starts it).
std::vector<Body> board_with_striker(const rules::MatchState& state) {
    std::vector<Body> bodies = state.bodies;
    const auto seat = static_cast<std::size_t>(state.turn_seat);
    if (seat < state.seats.size()) {
        bodies.push_back(rules::striker_for(state.physics, state.seats[seat].side,
                                            Shot{state.physics.centre().x, 0.0, 0.0}));
    }
    return stream_quantised(std::move(bodies));
}

proto::Error bad_entry(std::size_t entry, const rules::RuleError& error) {
    return proto::Error{std::string(proto::replay_code::kBadJournal),
                        "The rules refuse this input: " + error.message,
                        "entries[" + std::to_string(entry) + "]"};
}

proto::Phase phase_of(const rules::MatchState& state) {
    switch (state.phase) {
    case rules::Phase::GameOver:
        return proto::Phase::GameOver;
    case rules::Phase::BoardOver:
        return proto::Phase::BoardOver;
    default:
        return proto::Phase::Aiming;
    }
}

} // namespace

std::variant<ReplayModel, proto::Error> ReplayModel::load(const proto::MatchJournal& journal) {
    // The head alone: versions and configs, checked as replay() checks them.
    const proto::ReplayResult head = proto::replay(proto::MatchJournal{journal.created, {}});
    if (head.error) {
        return *head.error;
    }
    ReplayModel model;
    model.created_ = journal.created;
    model.initial_ = proto::initial_state(journal.created);
    rules::MatchState state = model.initial_;
    ExactEngine engine(journal.created.physics);
    rules::PlayOptions options;
    options.record_trajectory = true;
    double t = 0.0;
    for (std::size_t i = 0; i < journal.entries.size(); ++i) {
        const proto::JournalEvent& event = journal.entries[i].event;
        const proto::OutcomeRecord* record = proto::outcome_of(event);
        if (record == nullptr) {
            continue; // membership: no state change
        }
        ReplayTurn turn;
        turn.entry = i;
        turn.before = state;
        rules::PlayResult r;
        if (const auto* stroke = std::get_if<proto::StrokeEntry>(&event)) {
            r = rules::play_shot(state, stroke->seat, stroke->shot, engine, options);
            turn.stroke = true;
        } else if (const auto* expiry = std::get_if<proto::ClockExpiredEntry>(&event)) {
            r = rules::shot_clock_expired(state, expiry->seat);
        } else if (const auto* forfeit = std::get_if<proto::ForfeitEntry>(&event)) {
            r = rules::forfeit(state, forfeit->seat);
            turn.forfeit_reason =
                forfeit->reason == proto::ForfeitReason::Left ? "left" : "forfeit";
        }
        if (r.error) {
            return bad_entry(i, *r.error);
        }
        model.stroke_count_ += turn.stroke ? 1 : 0;
        turn.stroke_number = model.stroke_count_;
        turn.matches_journal = rules::hash_match_state(r.state) == record->state_hash;
        model.mismatches_ += turn.matches_journal ? 0 : 1;
        turn.start_s = t;
        turn.motion_s = t + kLeadS;
        turn.rest_s = turn.motion_s + (turn.stroke ? r.outcome.physics.end_time_s : 0.0);
        turn.end_s = turn.rest_s + kTailS;
        t = turn.end_s;
        turn.result = r.state;
        turn.outcome = std::move(r.outcome);
        state = std::move(r.state);
        if (state.phase == rules::Phase::BoardOver) {
            state = rules::start_next_board(state);
        }
        model.turns_.push_back(std::move(turn));
    }
    model.final_ = std::move(state);
    model.duration_s_ = t;
    return model;
}

std::variant<ReplayModel, proto::Error> ReplayModel::load_text(std::string_view text) {
    proto::Decoded<proto::MatchJournal> decoded = proto::decode_journal_text(text);
    if (decoded.error) {
        return *decoded.error;
    }
    return load(decoded.value);
}

void ReplayModel::play() {
    if (finished()) {
        time_s_ = 0.0;
    }
    playing_ = true;
}

void ReplayModel::toggle_play() {
    if (playing_) {
        pause();
    } else {
        play();
    }
}

void ReplayModel::set_speed(double speed) {
    speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed);
}

void ReplayModel::faster() {
    const auto it = std::upper_bound(kSpeeds.begin(), kSpeeds.end(), speed_);
    set_speed(it != kSpeeds.end() ? *it : kMaxSpeed);
}

void ReplayModel::slower() {
    const auto it = std::lower_bound(kSpeeds.begin(), kSpeeds.end(), speed_);
    set_speed(it != kSpeeds.begin() ? *(it - 1) : kMinSpeed);
}

void ReplayModel::advance(double wall_s) {
    if (!playing_ || wall_s <= 0.0) {
        return;
    }
    time_s_ = std::min(time_s_ + wall_s * speed_, duration_s_);
    if (finished()) {
        playing_ = false;
    }
}

void ReplayModel::seek(double time_s) {
    time_s_ = std::clamp(time_s, 0.0, duration_s_);
}

void ReplayModel::restart() {
    time_s_ = 0.0;
    playing_ = true;
}

void ReplayModel::next_turn() {
    if (turns_.empty()) {
        return;
    }
    const std::size_t i = current_turn();
    seek(i + 1 < turns_.size() ? turns_[i + 1].start_s : duration_s_);
}

void ReplayModel::previous_turn() {
    if (turns_.empty()) {
        return;
    }
    std::size_t i = current_turn();
    // Within the first moments of an input's lead: the input before it.
    if (!finished() && time_s_ <= turns_[i].start_s + 0.5 * kLeadS && i > 0) {
        --i;
    }
    seek(turns_[i].start_s);
}

std::size_t ReplayModel::turn_at(double time_s) const {
    const auto it =
        std::upper_bound(turns_.begin(), turns_.end(), time_s,
                         [](double t, const ReplayTurn& turn) { return t < turn.end_s; });
    return it == turns_.end() ? turns_.size() - 1 : static_cast<std::size_t>(it - turns_.begin());
}

int ReplayModel::stroke_number() const {
    if (turns_.empty()) {
        return 0;
    }
    const ReplayTurn& turn = turns_[current_turn()];
    return turn.stroke && time_s_ < turn.motion_s ? turn.stroke_number - 1 : turn.stroke_number;
}

int ReplayModel::turn_number() const {
    if (turns_.empty() || finished()) {
        return static_cast<int>(turns_.size());
    }
    const std::size_t i = current_turn();
    return static_cast<int>(i) + (time_s_ < turns_[i].motion_s ? 0 : 1);
}

const rules::MatchState& ReplayModel::state_at_time(double time_s) const {
    if (turns_.empty()) {
        return initial_;
    }
    if (time_s >= duration_s_) {
        return final_;
    }
    const ReplayTurn& turn = turns_[turn_at(time_s)];
    return time_s < turn.rest_s ? turn.before : turn.result;
}

std::optional<double> ReplayModel::shot_time_at(double time_s) const {
    if (turns_.empty()) {
        return std::nullopt;
    }
    const ReplayTurn& turn = turns_[turn_at(time_s)];
    if (!turn.stroke || time_s < turn.motion_s || time_s >= turn.rest_s) {
        return std::nullopt;
    }
    return time_s - turn.motion_s;
}

std::vector<Body> ReplayModel::bodies_at(double time_s) const {
    if (turns_.empty()) {
        return board_with_striker(initial_);
    }
    if (time_s >= duration_s_) {
        return board_with_striker(final_);
    }
    const ReplayTurn& turn = turns_[turn_at(time_s)];
    if (time_s >= turn.rest_s) {
        return board_with_striker(turn.result);
    }
    if (!turn.stroke) {
        return board_with_striker(turn.before);
    }
    const Trajectory& trajectory = turn.outcome.physics.trajectory;
    if (time_s < turn.motion_s) {
        std::vector<Body> bodies = trajectory.initial;
        for (Body& body : bodies) {
            body.vel_px_s = {}; // placed, not yet struck
        }
        return stream_quantised(std::move(bodies));
    }
    return bodies_in_stroke(turn_at(time_s), time_s - turn.motion_s);
}

std::vector<Body> ReplayModel::bodies_in_stroke(std::size_t turn, double shot_t_s) const {
    return stream_quantised(
        state_at(created_.physics, turns_[turn].outcome.physics.trajectory, shot_t_s));
}

proto::RoomState ReplayModel::room_state_at(double time_s) const {
    const rules::MatchState& m = state_at_time(time_s);
    proto::RoomState state;
    state.code = created_.room_code.empty() ? "REPLAY" : created_.room_code;
    state.you = -1;
    state.rule_set = wire_rule_set(m.rule_set);
    state.options.target_points = m.rule_set == rules::RuleSet::Freestyle
                                      ? m.config.freestyle.target
                                      : m.config.target_points;
    state.options.boards = m.config.max_boards;
    state.options.shot_clock_s = m.config.shot_clock_s;
    for (std::size_t i = 0; i < m.seats.size(); ++i) {
        proto::SeatInfo info;
        info.occupied = true;
        info.name = i < created_.seats.size() ? created_.seats[i].name : "";
        info.connected = true;
        info.bot = i < created_.seats.size() && created_.seats[i].bot;
        info.colour = room::colour_of_team(m, rules::team_of(m, static_cast<int>(i)));
        info.baseline = m.seats[i].side;
        info.team = rules::team_of(m, static_cast<int>(i));
        state.seats.push_back(std::move(info));
    }
    state.scores = room::per_seat(m, m.scores);
    state.dues = room::per_seat(m, m.dues_owed);
    state.board_number = m.board;
    state.turn = m.turn_number;
    state.to_play = m.turn_seat;
    state.phase = shot_time_at(time_s) ? proto::Phase::Moving : phase_of(m);
    state.queen = room::to_proto(m.queen);
    state.winner = m.result && m.result->winner_team ? *m.result->winner_team : -1;
    for (const Body& body : bodies_at(time_s)) {
        state.bodies.push_back(proto::to_board_body(body));
    }
    return state;
}

std::vector<proto::ServerMessage> ReplayModel::outcome_messages(std::size_t index) const {
    std::vector<proto::ServerMessage> out;
    if (index >= turns_.size()) {
        return out;
    }
    const ReplayTurn& turn = turns_[index];
    rules::MatchState after = turn.result;
    if (after.phase == rules::Phase::BoardOver) {
        after = rules::start_next_board(after);
    }
    out.emplace_back(room::to_shot_result(turn.outcome, after));
    for (proto::Event& event : room::rule_events(turn.outcome, turn.before, turn.result)) {
        if (auto* end = std::get_if<proto::GameEndEvent>(&event);
            end != nullptr && !turn.forfeit_reason.empty()) {
            end->reason = turn.forfeit_reason;
        }
        out.emplace_back(std::move(event));
    }
    return out;
}

} // namespace carrom::client
