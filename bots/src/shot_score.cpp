#include "carrom/bots/shot_score.hpp"

namespace carrom::bots {

namespace {

double kind_value(const rules::MatchState& before, int team, BodyKind kind, const ScoreWeights& w) {
    if (kind == BodyKind::Queen || kind == BodyKind::Striker) {
        return 0.0; // the queen is scored by its state
    }
    const auto own = rules::team_colour(before, team);
    if (!own) {
        return w.own_coin; // freestyle: any coin
    }
    return kind == *own ? w.own_coin : w.opponent_coin;
}

} // namespace

double score_outcome(const rules::MatchState& before, const rules::PlayResult& after, int seat,
                     const ScoreWeights& w) {
    const rules::ShotOutcome& outcome = after.outcome;
    const int team = rules::team_of(before, seat);
    double score = 0.0;
    for (const int id : outcome.pocketed) {
        if (id >= 0 && static_cast<std::size_t>(id) < before.bodies.size()) {
            score += kind_value(before, team, before.bodies[static_cast<std::size_t>(id)].kind, w);
        }
    }
    if (outcome.queen_after.seat >= 0 && rules::team_of(before, outcome.queen_after.seat) == team &&
        outcome.queen_after.status != outcome.queen_before.status) {
        if (outcome.queen_after.status == rules::QueenStatus::PendingCover) {
            score += w.queen_pending;
        } else if (outcome.queen_after.status == rules::QueenStatus::Covered) {
            score += w.queen_covered;
        }
    }
    score += w.foul * static_cast<double>(outcome.fouls.size());
    if (outcome.extra_stroke) {
        score += w.extra_stroke;
    }
    for (std::size_t t = 0; t < outcome.score_changes.size(); ++t) {
        const double sign = static_cast<int>(t) == team ? 1.0 : -1.0;
        score += sign * w.score_point * static_cast<double>(outcome.score_changes[t]);
    }
    if (outcome.board_end && outcome.board_end->winner_team) {
        score += *outcome.board_end->winner_team == team ? w.board_won : -w.board_won;
    }
    if (outcome.game_end && outcome.game_end->winner_team) {
        score += *outcome.game_end->winner_team == team ? w.game_won : -w.game_won;
    }
    return score;
}

} // namespace carrom::bots
