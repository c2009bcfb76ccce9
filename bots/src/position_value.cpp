#include "carrom/bots/position_value.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::bots {

namespace {

int other_team(int team) {
    return team == 0 ? 1 : 0;
}

double score_of(const rules::MatchState& state, int team) {
    const auto t = static_cast<std::size_t>(team);
    return t < state.scores.size() ? static_cast<double>(state.scores[t]) : 0.0;
}

double dues_of(const rules::MatchState& state, int team) {
    const auto t = static_cast<std::size_t>(team);
    return t < state.dues_owed.size() ? static_cast<double>(state.dues_owed[t]) : 0.0;
}

int boards_won(const rules::MatchState& state, int team) {
    return static_cast<int>(std::count_if(
        state.boards.begin(), state.boards.end(),
        [team](const rules::BoardResult& board) { return board.winner_team == team; }));
}

// The queen's part for team: + if the team holds it, - if the opponents do.
double queen_value(const rules::MatchState& state, int team, const ValueWeights& w) {
    if (state.queen.seat < 0) {
        return 0.0;
    }
    const double sign = rules::team_of(state, state.queen.seat) == team ? 1.0 : -1.0;
    switch (state.queen.status) {
    case rules::QueenStatus::PendingCover:
        return sign * w.queen_pending;
    case rules::QueenStatus::Covered:
        // seed and freestyle count the cover in the scores already
        return state.rule_set == rules::RuleSet::Icf ? sign * w.queen_covered : 0.0;
    case rules::QueenStatus::OnBoard:
    case rules::QueenStatus::OutOfPlay:
        break;
    }
    return 0.0;
}

// icf and discpool: coins off the board and dues, from team's side.
double colour_progress(const rules::MatchState& state, int team, const ValueWeights& w) {
    const auto own = rules::team_colour(state, team);
    const auto theirs = rules::team_colour(state, other_team(team));
    if (!own || !theirs) {
        return 0.0;
    }
    const double own_off = 9.0 - static_cast<double>(rules::count_on_board(state, *own));
    const double their_off = 9.0 - static_cast<double>(rules::count_on_board(state, *theirs));
    return w.own_coin * own_off - w.opponent_coin * their_off -
           w.due * (dues_of(state, team) - dues_of(state, other_team(team)));
}

} // namespace

bool wants_to_pocket(const rules::MatchState& state, int team, const Body& body) {
    if (body.pocketed || body.kind == BodyKind::Striker) {
        return false;
    }
    if (body.kind == BodyKind::Queen) {
        return state.queen.status == rules::QueenStatus::OnBoard;
    }
    const auto own = rules::team_colour(state, team);
    return !own || body.kind == *own;
}

double position_value(const rules::MatchState& state, int team, const ValueWeights& w) {
    const int them = other_team(team);
    if (state.phase == rules::Phase::GameOver && state.result) {
        if (!state.result->winner_team) {
            return 0.0;
        }
        return *state.result->winner_team == team ? w.game_won : -w.game_won;
    }
    double value =
        w.board_won * static_cast<double>(boards_won(state, team) - boards_won(state, them));
    value += queen_value(state, team, w);
    switch (state.rule_set) {
    case rules::RuleSet::Icf:
        value += colour_progress(state, team, w);
        value += w.game_point * (score_of(state, team) - score_of(state, them));
        break;
    case rules::RuleSet::DiscPool:
        value += colour_progress(state, team, w);
        break;
    case rules::RuleSet::Seed:
        value += w.seed_point * (score_of(state, team) - score_of(state, them));
        break;
    case rules::RuleSet::Freestyle:
        value += w.freestyle_point * (score_of(state, team) - score_of(state, them));
        break;
    }
    return value;
}

double easy_coins(const rules::MatchState& state, int team, const ValueWeights& w) {
    const auto pockets = state.physics.pocket_centres();
    double easy = 0.0;
    for (const Body& body : state.bodies) {
        if (!wants_to_pocket(state, team, body)) {
            continue;
        }
        double nearest_px = w.easy_range_px;
        for (const Vec2& pocket : pockets) {
            const double dx = body.pos_px.x - pocket.x;
            const double dy = body.pos_px.y - pocket.y;
            nearest_px =
                std::min(nearest_px, std::sqrt(dx * dx + dy * dy) - state.physics.pocket_radius_px);
        }
        easy += std::clamp(1.0 - nearest_px / w.easy_range_px, 0.0, 1.0);
    }
    return easy;
}

double turn_value(const rules::MatchState& state, int team, const ValueWeights& w) {
    if (state.phase != rules::Phase::AwaitingShot) {
        return 0.0;
    }
    const int next_team = rules::team_of(state, state.turn_seat);
    const double easy = w.easy_coin * easy_coins(state, next_team, w);
    return next_team == team ? w.keep_turn + easy : -easy;
}

} // namespace carrom::bots
