// discpool: each side owns the nine coins of one colour (the breaker's side white); no queen.
// Own coins pocketed earn another stroke; pocketing the striker returns them plus a due (as in
// icf) and passes the turn. First side whose coins are all off the board wins.

#include "stroke.hpp"

namespace carrom::rules::detail {
namespace {

void update_scores(MatchState& st) {
    for (int team = 0; team < 2; ++team) {
        st.scores[static_cast<std::size_t>(team)] = count_pocketed(st, *team_colour(st, team));
    }
}

} // namespace

bool judge_discpool(Stroke& s) {
    MatchState& st = s.state;
    const BodyKind own = *team_colour(st, s.team);
    const std::vector<int> own_in = of_kind(s, own);
    if (s.foul) {
        add_foul(s, RuleCode::StrikerPocketed);
        for (int id : own_in) {
            return_piece(s, id, RuleCode::StrikerPocketed);
        }
        st.dues_owed[static_cast<std::size_t>(s.team)] += 1;
        s.outcome.dues_incurred += 1;
    }
    pay_dues(s, own);
    update_scores(st);
    if (count_on_board(st, own) == 0) {
        end_board(s, s.team, 0, RuleCode::BoardCleared);
        return false;
    }
    if (count_on_board(st, other_colour(own)) == 0) {
        add_foul(s, RuleCode::OpponentLastCoin);
        end_board(s, other_team(s.team), 0, RuleCode::OpponentLastCoin);
        return false;
    }
    return !s.foul && !own_in.empty();
}

} // namespace carrom::rules::detail
