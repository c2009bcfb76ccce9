// freestyle: any coin scores for the shooter (white 20, black 10 by default); the queen scores
// when covered by any coin in the same or the next stroke; pocketing the striker costs points and
// the turn. First side to the target wins, or the higher score when the coins run out.

#include "stroke.hpp"

namespace carrom::rules::detail {
namespace {

int coin_value(const FreestylePoints& points, BodyKind kind) {
    switch (kind) {
    case BodyKind::White:
        return points.white;
    case BodyKind::Black:
        return points.black;
    case BodyKind::Queen:
    case BodyKind::Striker:
        break;
    }
    return 0;
}

int& score(Stroke& s) {
    return s.state.scores[static_cast<std::size_t>(s.team)];
}

void apply_freestyle_queen(Stroke& s, bool coin_in) {
    const bool queen_in = contains(s.in, kQueenId);
    if (!queen_in && !s.cover_stroke) {
        return;
    }
    if (s.foul) {
        return_queen(s, queen_in ? RuleCode::StrikerPocketed : RuleCode::QueenNotCovered);
    } else if (coin_in) {
        cover_queen(s);
        score(s) += s.state.config.freestyle.queen;
    } else if (queen_in) {
        s.state.queen = QueenState{QueenStatus::PendingCover, s.seat};
    } else {
        return_queen(s, RuleCode::QueenNotCovered);
    }
}

void check_freestyle_game_end(Stroke& s) {
    MatchState& st = s.state;
    if (score(s) >= st.config.freestyle.target) {
        end_board(s, s.team, 0, RuleCode::TargetPoints);
        return;
    }
    if (count_on_board(st, BodyKind::Black) + count_on_board(st, BodyKind::White) > 0) {
        return;
    }
    if (st.queen.status == QueenStatus::PendingCover) {
        return_queen(s, RuleCode::QueenNotCovered); // no coin is left to cover it
    }
    std::optional<int> winner;
    if (st.scores[0] != st.scores[1]) {
        winner = st.scores[0] > st.scores[1] ? 0 : 1;
    }
    end_board(s, winner, 0, RuleCode::CoinsExhausted);
}

} // namespace

bool judge_freestyle(Stroke& s) {
    bool coin_in = false;
    for (int id : s.in) {
        const int value = coin_value(s.state.config.freestyle, piece(s.state, id).kind);
        score(s) += value;
        coin_in = coin_in || id != kQueenId;
    }
    if (s.foul) {
        add_foul(s, RuleCode::StrikerPocketed);
        score(s) -= s.state.config.freestyle.striker_penalty;
    }
    apply_freestyle_queen(s, coin_in);
    check_freestyle_game_end(s);
    return !s.foul && (coin_in || s.state.queen.status == QueenStatus::PendingCover);
}

} // namespace carrom::rules::detail
