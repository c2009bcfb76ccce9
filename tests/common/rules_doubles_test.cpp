// Doubles (four seats, partners opposite) under the icf rules, scenario by scenario, as
// ../shared/reference/carrom-rules.md states them: partners sit opposite and the turn passes
// anticlockwise; a team's coins, dues, queen and score are shared by both partners.
// In the standard layout odd ids are black, even ids 2..18 white, 0 the queen; seat 0 breaks the
// first board, so team 0 (seats 0 and 2) plays white and team 1 (seats 1 and 3) black.

#include "rules_support.hpp"

#include <gtest/gtest.h>

namespace carrom::rules {
namespace {

using test::pre_pocket;
using test::stroke;

MatchState doubles() {
    RulesConfig config = test::no_clock();
    config.seat_count = 4;
    return test::broken(RuleSet::Icf, config);
}

// Plays strokes that pocket nothing until `seat` is to play.
MatchState until_turn_of(MatchState m, int seat) {
    for (int i = 0; i < 4 && m.turn_seat != seat; ++i) {
        m = stroke(m, {}).state;
    }
    return m;
}

TEST(RulesDoubles, TheTurnGoesRoundAnticlockwiseAndBackToTheBreaker) {
    MatchState m = doubles();
    std::vector<int> order;
    for (int i = 0; i < 5; ++i) {
        order.push_back(m.turn_seat);
        m = stroke(m, {}).state;
    }
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 0}));
}

TEST(RulesDoubles, APartnersColourIsOwnAndEarnsAnotherStroke) {
    MatchState m = until_turn_of(doubles(), 2);
    const StrokeResult r = stroke(m, {4}); // white: team 0's colour, seat 0's break
    EXPECT_TRUE(r.outcome.extra_stroke);
    EXPECT_EQ(r.state.turn_seat, 2);
    EXPECT_TRUE(r.outcome.fouls.empty());
}

TEST(RulesDoubles, AnOpponentsCoinStaysDownAndTheTurnPassesToTheNextSeat) {
    MatchState m = until_turn_of(doubles(), 3);
    const StrokeResult r = stroke(m, {4}); // seat 3 (black) pockets white
    EXPECT_FALSE(r.outcome.extra_stroke);
    EXPECT_EQ(r.state.turn_seat, 0);
    EXPECT_TRUE(r.state.bodies[4].pocketed);
}

TEST(RulesDoubles, TheQueenIsLegalOnceThePartnerHasPocketedAnOwnCoin) {
    MatchState m = until_turn_of(doubles(), 2);
    pre_pocket(m, 6, 0); // seat 0 pocketed a white coin earlier on this board
    StrokeResult r = stroke(m, {kQueenId});
    EXPECT_EQ(r.state.queen.status, QueenStatus::PendingCover);
    EXPECT_EQ(r.state.queen.seat, 2);
    EXPECT_EQ(r.state.turn_seat, 2); // a legal queen earns the cover stroke
    r = stroke(r.state, {8});        // covered by an own coin the very next stroke
    EXPECT_EQ(r.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(r.state.queen.seat, 2);
}

TEST(RulesDoubles, AQueenBeforeTheTeamHasAnOwnCoinComesBackAndTheTurnEnds) {
    MatchState m = until_turn_of(doubles(), 1);
    pre_pocket(m, 4, 0); // a white coin is off the board, but it is the other team's
    const StrokeResult r = stroke(m, {kQueenId});
    EXPECT_EQ(r.state.queen.status, QueenStatus::OnBoard);
    EXPECT_EQ(r.state.turn_seat, 2);
}

TEST(RulesDoubles, ADueIsTheTeamsAndEitherPartnerPaysIt) {
    MatchState m = until_turn_of(doubles(), 1);
    m = stroke(m, {}, true).state; // seat 1 pockets the striker alone: team 1 owes one
    EXPECT_EQ(m.dues_owed, (std::vector<int>{0, 1}));
    EXPECT_EQ(m.turn_seat, 2);
    m = stroke(m, {}).state;               // seat 2 misses
    const StrokeResult r = stroke(m, {3}); // seat 3, seat 1's partner, pockets black
    EXPECT_EQ(r.outcome.dues_paid, 1);
    EXPECT_EQ(r.state.dues_owed, (std::vector<int>{0, 0}));
    EXPECT_FALSE(r.state.bodies[3].pocketed); // the coin went back to the centre
}

TEST(RulesDoubles, TheStrikerWithOwnCoinsReturnsThemPlusADueAndTheShooterGoesOn) {
    MatchState m = until_turn_of(doubles(), 2);
    pre_pocket(m, 10, 0); // the partner's white coin, the one a due takes back
    const StrokeResult r = stroke(m, {4}, true);
    EXPECT_FALSE(r.state.bodies[4].pocketed);
    EXPECT_FALSE(r.state.bodies[10].pocketed); // the due: the team's latest own coin
    EXPECT_EQ(r.state.turn_seat, 2);
}

TEST(RulesDoubles, TheBreakPassesToTheNextSeatAndItsTeamPlaysWhite) {
    MatchState m = doubles();
    m.phase = Phase::BoardOver;
    const MatchState next = start_next_board(m);
    EXPECT_EQ(next.board, 2);
    EXPECT_EQ(next.breaker, 1);
    EXPECT_EQ(next.turn_seat, 1);
    EXPECT_EQ(team_colour(next, 1), BodyKind::White);
    EXPECT_EQ(team_colour(next, team_of(next, 3)), BodyKind::White);
    EXPECT_EQ(team_colour(next, team_of(next, 2)), BodyKind::Black);
}

TEST(RulesDoubles, ClearingTheTeamsCoinsWinsTheBoardForBothPartners) {
    MatchState m = until_turn_of(doubles(), 2);
    for (int id = 2; id <= 16; id += 2) {
        pre_pocket(m, id, id % 4 == 0 ? 0 : 2); // eight whites, by both partners
    }
    pre_pocket(m, kQueenId, 0);
    m.queen = QueenState{QueenStatus::Covered, 0};
    pre_pocket(m, 1, 1); // one black down: eight left
    const StrokeResult r = stroke(m, {18});
    ASSERT_TRUE(r.outcome.board_end.has_value());
    EXPECT_EQ(r.outcome.board_end->winner_team, 0);
    EXPECT_EQ(r.outcome.board_end->points, 8 + 3); // the other team's coins left + the queen
    EXPECT_EQ(r.state.scores, (std::vector<int>{11, 0}));
}

TEST(RulesDoubles, AForfeitBySeatThreeLosesTheGameForItsTeam) {
    const PlayResult r = forfeit(doubles(), 3);
    ASSERT_FALSE(r.error.has_value());
    EXPECT_EQ(r.state.result->winner_team, 0);
}

TEST(RulesDoubles, MissedTurnsCountPerSeatAndThreeInARowLoseTheGame) {
    MatchState m = doubles();
    for (int round = 0; round < 2; ++round) {
        m = stroke(m, {}).state;            // seat 0 plays
        m = shot_clock_expired(m, 1).state; // seat 1 misses its turn
        m = stroke(m, {}).state;            // seat 2 plays
        m = stroke(m, {}).state;            // seat 3, seat 1's partner, plays
    }
    EXPECT_EQ(m.missed_turns, (std::vector<int>{0, 2, 0, 0}));
    m = stroke(m, {}).state;
    const PlayResult r = shot_clock_expired(m, 1);
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    ASSERT_TRUE(r.outcome.game_end.has_value());
    EXPECT_EQ(r.outcome.game_end->winner_team, 0);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::MissedTurns);
}

TEST(RulesDoubles, ASideSeatsPlacementIsCheckedAlongItsOwnBaseline) {
    MatchState m = until_turn_of(doubles(), 1);
    // Seat 1 shoots from x = 520; a coin on its baseline at y = 300 blocks that spot only.
    m.bodies[5].pos_px = {520.0, 300.0};
    const auto blocked = check_placement(m, 1, Shot{300.0, 3.14, 10.0});
    ASSERT_TRUE(blocked.has_value());
    EXPECT_EQ(blocked->code, RuleErrorCode::StrikerOverlaps);
    EXPECT_FALSE(check_placement(m, 1, Shot{200.0, 3.14, 10.0}).has_value());
    EXPECT_FALSE(check_placement(m, 0, Shot{300.0, -1.5, 10.0}).has_value()); // the bottom is free
}

} // namespace
} // namespace carrom::rules
