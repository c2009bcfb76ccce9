// icf: official carrom (../shared/reference/carrom-rules.md, docs/rules.md).

#include "stroke.hpp"

#include <algorithm>

namespace carrom::rules::detail {
namespace {

// A break that touched no piece moved nothing: the breaker tries again, up to break_tries times,
// then the turn passes.
bool missed_break(Stroke& s) {
    MatchState& st = s.state;
    add_foul(s, RuleCode::BreakMissed);
    st.break_tries += 1;
    return st.break_tries < st.config.break_tries;
}

// Applies the striker foul or the queen rules; returns whether the shooter shoots again.
bool apply_pockets(Stroke& s, BodyKind own, int own_before) {
    const std::vector<int> own_in = of_kind(s, own);
    const bool queen_in = contains(s.in, kQueenId);
    if (s.foul) {
        add_foul(s, RuleCode::StrikerPocketed);
        for (int id : own_in) {
            return_piece(s, id, RuleCode::StrikerPocketed);
        }
        if (queen_in) {
            return_queen(s, RuleCode::StrikerPocketed);
        } else if (s.cover_stroke) {
            return_queen(s, RuleCode::QueenNotCovered);
        }
        s.state.dues_owed[static_cast<std::size_t>(s.team)] += 1;
        s.outcome.dues_incurred += 1;
        return !own_in.empty();
    }
    if (s.cover_stroke) {
        if (own_in.empty()) {
            return_queen(s, RuleCode::QueenNotCovered);
        } else {
            cover_queen(s);
        }
    }
    if (queen_in) {
        if (!own_in.empty()) {
            cover_queen(s);
        } else if (own_before > 0) {
            s.state.queen = QueenState{QueenStatus::PendingCover, s.seat};
        } else {
            return_queen(s, RuleCode::QueenBeforeOwnCoin);
        }
    }
    return !own_in.empty() || s.state.queen.status == QueenStatus::PendingCover;
}

int capped(const MatchState& st, int points) {
    return std::min(points, st.config.board_points_cap);
}

// The last-coin laws and the board win; returns true when the board ended.
bool check_board_end(Stroke& s, BodyKind own) {
    MatchState& st = s.state;
    const int own_left = count_on_board(st, own);
    const int opp_left = count_on_board(st, other_colour(own));
    const int opponent = other_team(s.team);
    if (opp_left == 0) {
        add_foul(s, RuleCode::OpponentLastCoin);
        end_board(s, opponent, capped(st, st.config.queen_points + own_left),
                  RuleCode::OpponentLastCoin);
        return true;
    }
    if (own_left > 0) {
        return false;
    }
    if (st.queen.status != QueenStatus::Covered) {
        add_foul(s, RuleCode::OwnLastCoinBeforeQueen);
        end_board(s, opponent, capped(st, st.config.queen_points),
                  RuleCode::OwnLastCoinBeforeQueen);
        return true;
    }
    const bool our_queen = team_of(st, st.queen.seat) == s.team;
    const bool below_limit =
        st.scores[static_cast<std::size_t>(s.team)] < st.config.queen_points_limit;
    const int queen = our_queen && below_limit ? st.config.queen_points : 0;
    end_board(s, s.team, capped(st, opp_left + queen), RuleCode::BoardCleared);
    return true;
}

} // namespace

bool judge_icf(Stroke& s) {
    MatchState& st = s.state;
    if (!st.break_done) {
        if (!s.touched) {
            return missed_break(s);
        }
        st.break_done = true;
    }
    const BodyKind own = *team_colour(st, s.team);
    // Own coins off the board before this stroke (the queen may be pocketed only after one).
    const int own_before = count_pocketed(st, own) - static_cast<int>(of_kind(s, own).size());
    const bool extra = apply_pockets(s, own, own_before);
    pay_dues(s, own);
    return !check_board_end(s, own) && extra;
}

} // namespace carrom::rules::detail
