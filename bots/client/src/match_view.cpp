#include "carrom/bots/match_view.hpp"

#include "carrom/rules/match.hpp"
#include "carrom/scene.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace carrom::bots {

namespace {

rules::RulesConfig rules_config_from(const proto::RoomState& room) {
    rules::RulesConfig config;
    config.seat_count = room.seats.size() == 4 ? 4 : 2; // doubles: four seats, partners opposite
    config.shot_clock_s = room.options.shot_clock_s;
    if (room.rule_set == proto::RuleSet::Freestyle) {
        config.freestyle.target = room.options.target_points;
    } else {
        config.target_points = room.options.target_points;
    }
    config.max_boards = room.options.boards;
    return config;
}

rules::QueenState queen_from(const proto::QueenInfo& queen) {
    rules::QueenState out;
    out.seat = queen.seat;
    switch (queen.state) {
    case proto::QueenState::OnBoard:
        out.status = rules::QueenStatus::OnBoard;
        break;
    case proto::QueenState::Pending:
        out.status = rules::QueenStatus::PendingCover;
        break;
    case proto::QueenState::Covered:
        out.status = rules::QueenStatus::Covered;
        break;
    case proto::QueenState::None:
        out.status = rules::QueenStatus::OutOfPlay;
        break;
    }
    return out;
}

// The first n entries of values (0 for missing ones). room_state carries one entry per seat, each
// its team's value; teams 0 and 1 are seats 0 and 1, so the first entries are the teams' values.
std::vector<int> per_team(const std::vector<int>& values, std::size_t n) {
    std::vector<int> out(values.begin(),
                         values.begin() + static_cast<std::ptrdiff_t>(std::min(values.size(), n)));
    out.resize(n, 0);
    return out;
}

bool moved_from_layout(const rules::MatchState& state) {
    const auto layout = standard_layout(state.physics);
    for (std::size_t i = 0; i < layout.size() && i < state.bodies.size(); ++i) {
        const Body& now = state.bodies[i];
        if (now.pocketed || std::abs(now.pos_px.x - layout[i].pos_px.x) > 0.5 ||
            std::abs(now.pos_px.y - layout[i].pos_px.y) > 0.5) {
            return true;
        }
    }
    return false;
}

} // namespace

rules::MatchState match_state_from(const proto::RoomState& room, const PhysicsConfig& physics) {
    rules::MatchState state =
        rules::new_match(to_rules(room.rule_set), rules_config_from(room), physics);
    for (const proto::BoardBody& body : room.bodies) {
        if (body.id < 0 || static_cast<std::size_t>(body.id) >= state.bodies.size()) {
            continue; // the striker, or nothing the rules track
        }
        Body& piece = state.bodies[static_cast<std::size_t>(body.id)];
        piece = to_body(body);
        if (piece.pocketed) {
            state.pocketed.push_back({body.id, piece.kind, 0, 0});
        }
    }
    const std::size_t teams = state.scores.size();
    state.scores = per_team(room.scores, teams);
    state.dues_owed = per_team(room.dues, teams);
    state.board = std::max(1, room.board_number);
    state.turn_seat = std::clamp(room.to_play, 0, static_cast<int>(state.seats.size()) - 1);
    state.turn_number = room.turn;
    state.queen = queen_from(room.queen);
    // The breaker's team plays white: the first seat playing white, or (before the break, in
    // doubles) the white seat to play, which is the breaker itself.
    const bool breaker_plays_white =
        room.rule_set == proto::RuleSet::Icf || room.rule_set == proto::RuleSet::DiscPool;
    std::vector<int> white_seats;
    for (std::size_t s = 0; s < room.seats.size() && s < state.seats.size(); ++s) {
        if (breaker_plays_white && room.seats[s].colour == proto::Colour::White) {
            white_seats.push_back(static_cast<int>(s));
        }
    }
    state.break_done = moved_from_layout(state);
    if (!white_seats.empty()) {
        const bool turn_is_white =
            std::find(white_seats.begin(), white_seats.end(), state.turn_seat) != white_seats.end();
        state.breaker = !state.break_done && turn_is_white ? state.turn_seat : white_seats.front();
    }
    state.strokes_this_board = state.break_done ? 1 : 0;
    if (room.phase == proto::Phase::GameOver) {
        state.phase = rules::Phase::GameOver;
        state.result = rules::GameResult{};
        if (room.winner >= 0) {
            state.result->winner_team = room.winner;
        }
    } else if (room.phase == proto::Phase::BoardOver) {
        state.phase = rules::Phase::BoardOver;
    }
    return state;
}

} // namespace carrom::bots
