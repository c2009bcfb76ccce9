// seed: the seed game's rules (sections 05-06 of the tech note) with its defects fixed; each fix
// is listed in docs/rules.md. Team 0 plays black from the bottom, team 1 white from the top;
// every black pocketed scores for team 0 and every white for team 1, whoever pocketed it.

#include "stroke.hpp"

#include <algorithm>

namespace carrom::rules::detail {
namespace {

int scoring_team(BodyKind kind) {
    return kind == BodyKind::Black ? 0 : 1;
}

void score_pocketed_coins(Stroke& s) {
    for (int id : s.in) {
        const BodyKind kind = piece(s.state, id).kind;
        if (kind == BodyKind::Black || kind == BodyKind::White) {
            s.state.scores[static_cast<std::size_t>(scoring_team(kind))] += 1;
        }
    }
}

// The seed's returnPieceToCenter: the shooter's most recently pocketed own coin comes back and
// its point is taken away; nothing happens when there is none.
void return_last_own_coin(Stroke& s, BodyKind own) {
    const auto& list = s.state.pocketed;
    auto it = std::find_if(list.rbegin(), list.rend(),
                           [own](const PocketedPiece& p) { return p.kind == own; });
    if (it == list.rend()) {
        return;
    }
    return_piece(s, it->id, RuleCode::StrikerPocketed);
    s.state.scores[static_cast<std::size_t>(scoring_team(own))] -= 1;
}

void cover_with_bonus(Stroke& s) {
    cover_queen(s);
    s.state.scores[static_cast<std::size_t>(s.team)] += s.state.config.queen_points;
}

// The queen rules, fixed: pocketing the queen earns another stroke, and the queen is covered by
// an own coin in the same or that next stroke (the seed's code only allowed the same one). The
// seed checks the cover on the stroke's pocketed list even on a foul; we keep that, but a foul
// passes the turn, so an uncovered queen comes back at once.
void apply_seed_queen(Stroke& s, bool own_in) {
    const bool queen_in = contains(s.in, kQueenId);
    if (!queen_in && !s.cover_stroke) {
        return;
    }
    if (own_in) {
        cover_with_bonus(s);
    } else if (queen_in && !s.foul) {
        s.state.queen = QueenState{QueenStatus::PendingCover, s.seat};
    } else {
        return_queen(s, RuleCode::QueenNotCovered);
    }
}

void check_seed_game_end(Stroke& s) {
    MatchState& st = s.state;
    const bool black_cleared = count_on_board(st, BodyKind::Black) == 0;
    const bool white_cleared = count_on_board(st, BodyKind::White) == 0;
    if (!black_cleared && !white_cleared) {
        return;
    }
    if (st.queen.status == QueenStatus::PendingCover) {
        return_queen(s, RuleCode::QueenNotCovered); // no stroke is left to cover it
    }
    std::optional<int> winner;
    if (st.scores[0] != st.scores[1]) {
        winner = st.scores[0] > st.scores[1] ? 0 : 1;
    } else if (black_cleared != white_cleared) {
        winner = black_cleared ? 0 : 1;
    }
    end_board(s, winner, 0, RuleCode::ColourCleared);
}

} // namespace

bool judge_seed(Stroke& s) {
    const BodyKind own = *team_colour(s.state, s.team);
    const bool own_in = !of_kind(s, own).empty();
    score_pocketed_coins(s);
    if (s.foul) {
        add_foul(s, RuleCode::StrikerPocketed);
        return_last_own_coin(s, own);
    }
    apply_seed_queen(s, own_in);
    check_seed_game_end(s);
    return !s.foul && (own_in || s.state.queen.status == QueenStatus::PendingCover);
}

} // namespace carrom::rules::detail
