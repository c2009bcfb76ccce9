// icf rules, judged from chosen pocketed sets (no physics): every law in
// ../shared/reference/carrom-rules.md that the rules engine decides.

#include "rules_support.hpp"

#include <gtest/gtest.h>

namespace carrom::rules {
namespace {

using test::broken;
using test::ids_of;
using test::kBlack;
using test::kBlack2;
using test::kWhite;
using test::kWhite2;
using test::pre_pocket;
using test::stroke;

TEST(RulesIcf, NewMatchBreakerPlaysWhiteFromTheBottom) {
    const MatchState m = test::match(RuleSet::Icf);
    EXPECT_EQ(m.turn_seat, 0);
    EXPECT_EQ(m.breaker, 0);
    EXPECT_EQ(m.board, 1);
    EXPECT_EQ(m.turn_number, 0);
    EXPECT_EQ(m.phase, Phase::AwaitingShot);
    EXPECT_EQ(team_colour(m, 0), BodyKind::White);
    EXPECT_EQ(team_colour(m, 1), BodyKind::Black);
    EXPECT_EQ(m.seats[0].side, Side::Bottom);
    EXPECT_EQ(m.seats[1].side, Side::Top);
    ASSERT_EQ(m.bodies.size(), 19u);
    EXPECT_EQ(count_on_board(m, BodyKind::White), 9);
    EXPECT_EQ(count_on_board(m, BodyKind::Black), 9);
    EXPECT_EQ(m.queen.status, QueenStatus::OnBoard);
    EXPECT_EQ(m.scores, (std::vector<int>{0, 0}));
}

TEST(RulesIcf, OwnCoinEarnsAnotherStroke) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {kWhite});
    EXPECT_TRUE(r.outcome.extra_stroke);
    EXPECT_EQ(r.state.turn_seat, 0);
    EXPECT_EQ(r.state.turn_number, 1);
    ASSERT_EQ(r.state.pocketed.size(), 1u);
    EXPECT_EQ(r.state.pocketed[0].id, kWhite);
    EXPECT_TRUE(r.outcome.fouls.empty());
}

TEST(RulesIcf, OpponentCoinStaysAndTheTurnPasses) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {kBlack});
    EXPECT_FALSE(r.outcome.extra_stroke);
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_TRUE(r.state.bodies[kBlack].pocketed);
    EXPECT_TRUE(r.outcome.returned.empty());
}

TEST(RulesIcf, OwnAndOpponentCoinsKeepTheTurn) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {kBlack, kWhite});
    EXPECT_TRUE(r.outcome.extra_stroke);
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kBlack, kWhite}));
}

TEST(RulesIcf, NothingPocketedPassesTheTurn) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {});
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_EQ(r.outcome.next_seat, 1);
}

TEST(RulesIcf, StrikerAloneOwesADueWhenNothingIsPocketed) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {}, true);
    ASSERT_EQ(r.outcome.fouls.size(), 1u);
    EXPECT_EQ(r.outcome.fouls[0].code, RuleCode::StrikerPocketed);
    EXPECT_EQ(r.outcome.dues_incurred, 1);
    EXPECT_EQ(r.outcome.dues_paid, 0);
    EXPECT_EQ(r.state.dues_owed, (std::vector<int>{1, 0}));
    EXPECT_EQ(r.state.turn_seat, 1);
}

TEST(RulesIcf, StrikerAlonePaysADueFromPocketedCoins) {
    MatchState m = broken(RuleSet::Icf);
    pre_pocket(m, kWhite, 0);
    pre_pocket(m, kWhite2, 0);
    const StrokeResult r = stroke(m, {}, true);
    ASSERT_EQ(r.outcome.returned.size(), 1u);
    EXPECT_EQ(r.outcome.returned[0].id, kWhite2); // the most recently pocketed one
    EXPECT_EQ(r.outcome.returned[0].reason, RuleCode::DuePaid);
    EXPECT_EQ(r.outcome.dues_paid, 1);
    EXPECT_EQ(r.state.dues_owed[0], 0);
    EXPECT_FALSE(r.state.bodies[kWhite2].pocketed);
    EXPECT_EQ(r.state.turn_seat, 1);
}

TEST(RulesIcf, StrikerWithOwnCoinsReturnsThemPlusADueAndShootsAgain) {
    MatchState m = broken(RuleSet::Icf);
    pre_pocket(m, 6, 0);
    const StrokeResult r = stroke(m, {kWhite, kWhite2}, true);
    ASSERT_EQ(r.outcome.returned.size(), 3u);
    EXPECT_EQ(r.outcome.returned[0].id, kWhite);
    EXPECT_EQ(r.outcome.returned[0].reason, RuleCode::StrikerPocketed);
    EXPECT_EQ(r.outcome.returned[1].id, kWhite2);
    EXPECT_EQ(r.outcome.returned[2].id, 6);
    EXPECT_EQ(r.outcome.returned[2].reason, RuleCode::DuePaid);
    EXPECT_EQ(count_on_board(r.state, BodyKind::White), 9);
    EXPECT_TRUE(r.outcome.extra_stroke);
    EXPECT_EQ(r.state.turn_seat, 0);
    EXPECT_FALSE(test::overlaps_any(r.state));
}

TEST(RulesIcf, StrikerWithOpponentCoinsLeavesThemPocketedAndLosesTheTurn) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {kBlack}, true);
    EXPECT_TRUE(r.state.bodies[kBlack].pocketed);
    EXPECT_EQ(r.state.dues_owed[0], 1);
    EXPECT_EQ(r.state.turn_seat, 1);
}

TEST(RulesIcf, DueOwedIsPaidWithTheNextOwnCoin) {
    MatchState m = broken(RuleSet::Icf);
    m = stroke(m, {}, true).state; // seat 0 owes one
    m = stroke(m, {}).state;       // seat 1 misses
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.outcome.dues_paid, 1);
    EXPECT_EQ(r.state.dues_owed[0], 0);
    ASSERT_EQ(r.outcome.returned.size(), 1u);
    EXPECT_EQ(r.outcome.returned[0].id, kWhite);
    EXPECT_FALSE(r.state.bodies[kWhite].pocketed);
    EXPECT_TRUE(r.outcome.extra_stroke); // the coin was pocketed legally
}

TEST(RulesIcf, DuesAccumulate) {
    MatchState m = broken(RuleSet::Icf);
    m = stroke(m, {}, true).state;
    m = stroke(m, {}).state;
    m = stroke(m, {}, true).state;
    EXPECT_EQ(m.dues_owed[0], 2);
    m = stroke(m, {}).state;
    const StrokeResult r = stroke(m, {kWhite, kWhite2, 6});
    EXPECT_EQ(r.outcome.dues_paid, 2);
    EXPECT_EQ(r.state.dues_owed[0], 0);
    EXPECT_EQ(count_on_board(r.state, BodyKind::White), 8);
}

TEST(RulesIcf, QueenBeforeAnyOwnCoinComesBackAndTheTurnEnds) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {kQueenId});
    ASSERT_EQ(r.outcome.returned.size(), 1u);
    EXPECT_EQ(r.outcome.returned[0].reason, RuleCode::QueenBeforeOwnCoin);
    EXPECT_EQ(r.state.queen.status, QueenStatus::OnBoard);
    EXPECT_FALSE(r.state.bodies[kQueenId].pocketed);
    EXPECT_EQ(r.state.turn_seat, 1);
}

TEST(RulesIcf, QueenWithOwnCoinIsCoveredInTheSameStroke) {
    const StrokeResult r = stroke(broken(RuleSet::Icf), {kQueenId, kWhite});
    EXPECT_EQ(r.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(r.state.queen.seat, 0);
    EXPECT_TRUE(r.outcome.extra_stroke);
}

TEST(RulesIcf, QueenThenCoverOnTheNextStroke) {
    MatchState m = broken(RuleSet::Icf);
    pre_pocket(m, kWhite, 0);
    const StrokeResult first = stroke(m, {kQueenId});
    EXPECT_EQ(first.state.queen.status, QueenStatus::PendingCover);
    EXPECT_EQ(first.state.queen.seat, 0);
    EXPECT_TRUE(first.outcome.extra_stroke);
    const StrokeResult second = stroke(first.state, {kWhite2});
    EXPECT_EQ(second.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(second.outcome.queen_before.status, QueenStatus::PendingCover);
    EXPECT_EQ(second.outcome.queen_after.status, QueenStatus::Covered);
    EXPECT_TRUE(second.state.bodies[kQueenId].pocketed);
}

TEST(RulesIcf, QueenUncoveredComesBackAndTheTurnPasses) {
    MatchState m = broken(RuleSet::Icf);
    pre_pocket(m, kWhite, 0);
    const StrokeResult first = stroke(m, {kQueenId});
    const StrokeResult second = stroke(first.state, {kBlack});
    EXPECT_EQ(second.state.queen.status, QueenStatus::OnBoard);
    ASSERT_EQ(second.outcome.returned.size(), 1u);
    EXPECT_EQ(second.outcome.returned[0].id, kQueenId);
    EXPECT_EQ(second.outcome.returned[0].reason, RuleCode::QueenNotCovered);
    // The queen's own spot at the centre is free again, so it goes back exactly there.
    EXPECT_EQ(second.outcome.returned[0].pos_px, (Vec2{300.0, 300.0}));
    EXPECT_EQ(second.state.turn_seat, 1);
}

TEST(RulesIcf, QueenPendingIsLostOnAFoul) {
    MatchState m = broken(RuleSet::Icf);
    pre_pocket(m, kWhite, 0);
    const StrokeResult first = stroke(m, {kQueenId});
    const StrokeResult second = stroke(first.state, {kWhite2}, true);
    EXPECT_EQ(second.state.queen.status, QueenStatus::OnBoard);
    EXPECT_FALSE(second.state.bodies[kQueenId].pocketed);
    EXPECT_FALSE(second.state.bodies[kWhite2].pocketed);
}

TEST(RulesIcf, QueenWithStrikerComesBack) {
    MatchState m = broken(RuleSet::Icf);
    pre_pocket(m, kWhite, 0);
    const StrokeResult r = stroke(m, {kQueenId}, true);
    EXPECT_EQ(r.state.queen.status, QueenStatus::OnBoard);
    EXPECT_FALSE(r.state.bodies[kQueenId].pocketed);
}

// Pockets every coin of kind except `keep` (by seat) before the stroke.
MatchState with_all_but(MatchState m, BodyKind kind, int keep, int seat) {
    for (int id : ids_of(m, kind)) {
        if (id != keep) {
            pre_pocket(m, id, seat);
        }
    }
    return m;
}

TEST(RulesIcf, OwnLastCoinBeforeTheQueenLosesTheBoard) {
    const MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    const StrokeResult r = stroke(m, {kWhite});
    ASSERT_TRUE(r.outcome.board_end.has_value());
    EXPECT_EQ(r.outcome.board_end->winner_team, 1);
    EXPECT_EQ(r.outcome.board_end->points, 3);
    EXPECT_EQ(r.outcome.board_end->reason, RuleCode::OwnLastCoinBeforeQueen);
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 3}));
    EXPECT_EQ(r.outcome.score_changes, (std::vector<int>{0, 3}));
    EXPECT_EQ(r.state.phase, Phase::BoardOver);
    EXPECT_FALSE(r.outcome.extra_stroke);
}

TEST(RulesIcf, OpponentsLastCoinLosesTheBoard) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::Black, kBlack, 1);
    pre_pocket(m, kWhite, 0);
    pre_pocket(m, kWhite2, 0);
    pre_pocket(m, 6, 0);
    const StrokeResult r = stroke(m, {kBlack});
    ASSERT_TRUE(r.outcome.board_end.has_value());
    EXPECT_EQ(r.outcome.board_end->winner_team, 1);
    EXPECT_EQ(r.outcome.board_end->points, 3 + 6); // 3 plus the shooter's 6 coins left
    EXPECT_EQ(r.outcome.board_end->reason, RuleCode::OpponentLastCoin);
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 9}));
}

TEST(RulesIcf, OpponentsLastCoinPointsAreCapped) {
    const MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::Black, kBlack, 1);
    const StrokeResult r = stroke(m, {kBlack});
    EXPECT_EQ(r.outcome.board_end->points, 12); // 3 + 9, the cap
    RulesConfig config = test::no_clock();
    config.board_points_cap = 10;
    MatchState capped = with_all_but(broken(RuleSet::Icf, config), BodyKind::Black, kBlack, 1);
    EXPECT_EQ(stroke(capped, {kBlack}).outcome.board_end->points, 10);
}

TEST(RulesIcf, ClearingAfterCoveringTheQueenWinsWithQueenPoints) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.queen = QueenState{QueenStatus::Covered, 0};
    pre_pocket(m, kQueenId, 0);
    pre_pocket(m, kBlack, 1);
    const StrokeResult r = stroke(m, {kWhite});
    ASSERT_TRUE(r.outcome.board_end.has_value());
    EXPECT_EQ(r.outcome.board_end->winner_team, 0);
    EXPECT_EQ(r.outcome.board_end->points, 8 + 3);
    EXPECT_EQ(r.outcome.board_end->reason, RuleCode::BoardCleared);
    EXPECT_EQ(r.state.scores, (std::vector<int>{11, 0}));
}

TEST(RulesIcf, QueenCoveredByTheOpponentGivesTheWinnerNoQueenPoints) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.queen = QueenState{QueenStatus::Covered, 1};
    pre_pocket(m, kQueenId, 1);
    EXPECT_EQ(stroke(m, {kWhite}).outcome.board_end->points, 9);
}

TEST(RulesIcf, NoQueenPointsAtTwentyTwoOrMore) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.queen = QueenState{QueenStatus::Covered, 0};
    pre_pocket(m, kQueenId, 0);
    m.scores = {22, 0};
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.outcome.board_end->points, 9);
    m.scores = {21, 0};
    EXPECT_EQ(stroke(m, {kWhite}).outcome.board_end->points, 12);
}

TEST(RulesIcf, LastCoinTogetherWithTheQueenCoversAndWins) {
    const MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    const StrokeResult r = stroke(m, {kQueenId, kWhite});
    EXPECT_EQ(r.outcome.board_end->winner_team, 0);
    EXPECT_EQ(r.outcome.board_end->points, 12);
}

TEST(RulesIcf, LastCoinWithTheStrikerComesBack) {
    const MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    const StrokeResult r = stroke(m, {kWhite}, true);
    EXPECT_FALSE(r.outcome.board_end.has_value());
    // The coin comes back and then pays the due: two of the eight come back.
    EXPECT_EQ(count_on_board(r.state, BodyKind::White), 2);
    EXPECT_EQ(r.state.dues_owed[0], 0);
}

TEST(RulesIcf, GameEndsAtTheTargetScore) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.queen = QueenState{QueenStatus::Covered, 0};
    pre_pocket(m, kQueenId, 0);
    m.scores = {20, 12};
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    ASSERT_TRUE(r.outcome.game_end.has_value());
    EXPECT_EQ(r.outcome.game_end->winner_team, 0);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::TargetPoints);
    EXPECT_EQ(r.state.result->winner_team, 0);
    EXPECT_EQ(r.state.scores[0], 32);
}

TEST(RulesIcf, GameEndsAfterTheLastBoardWithALeader) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.board = 8;
    m.scores = {5, 7};
    const StrokeResult r = stroke(m, {kWhite}); // own last coin before the queen: team 1 +3
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.outcome.game_end->winner_team, 1);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::BoardsPlayed);
}

TEST(RulesIcf, TieAfterTheLastBoardPlaysATieBreakBoard) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.board = 8;
    m.scores = {10, 7};
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.state.scores, (std::vector<int>{10, 10}));
    EXPECT_EQ(r.state.phase, Phase::BoardOver);
    const MatchState ninth = start_next_board(r.state);
    EXPECT_EQ(ninth.board, 9);
    EXPECT_EQ(ninth.phase, Phase::AwaitingShot);
}

TEST(RulesIcf, TheBreakAlternatesAndTheBreakerPlaysWhite) {
    const MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.outcome.next_seat, 1);
    const MatchState next = start_next_board(r.state);
    EXPECT_EQ(next.board, 2);
    EXPECT_EQ(next.breaker, 1);
    EXPECT_EQ(next.turn_seat, 1);
    EXPECT_EQ(next.turn_number, r.state.turn_number + 1);
    EXPECT_EQ(team_colour(next, 1), BodyKind::White);
    EXPECT_EQ(team_colour(next, 0), BodyKind::Black);
    EXPECT_TRUE(next.pocketed.empty());
    EXPECT_EQ(next.queen.status, QueenStatus::OnBoard);
    EXPECT_EQ(count_on_board(next, BodyKind::White), 9);
    EXPECT_FALSE(next.break_done);
    EXPECT_EQ(next.scores, r.state.scores);
    ASSERT_EQ(next.boards.size(), 1u);
    EXPECT_EQ(next.boards[0].board, 1);
}

TEST(RulesIcf, StartNextBoardDoesNothingMidBoard) {
    const MatchState m = test::match(RuleSet::Icf);
    const MatchState same = start_next_board(m);
    EXPECT_EQ(same.board, 1);
    EXPECT_EQ(same.turn_number, m.turn_number);
}

StrokeResult missed_break(const MatchState& m) {
    StrokePhysics physics = test::pocketing(m, {});
    physics.striker_touched_coin = false;
    return judge_stroke(m, m.turn_seat, Shot{}, physics);
}

TEST(RulesIcf, ABreakMustTouchACoinWithinThreeTries) {
    MatchState m = test::match(RuleSet::Icf);
    for (int attempt = 1; attempt <= 2; ++attempt) {
        const StrokeResult r = missed_break(m);
        ASSERT_EQ(r.outcome.fouls.size(), 1u);
        EXPECT_EQ(r.outcome.fouls[0].code, RuleCode::BreakMissed);
        EXPECT_EQ(r.state.turn_seat, 0) << attempt;
        m = r.state;
    }
    const StrokeResult third = missed_break(m);
    EXPECT_EQ(third.state.turn_seat, 1);
    EXPECT_EQ(third.state.break_tries, 0);
    EXPECT_FALSE(third.state.break_done);
    const StrokeResult touched = stroke(third.state, {});
    EXPECT_TRUE(touched.state.break_done);
}

TEST(RulesIcf, StrikerPocketedOnAMissedBreakCostsNoDue) {
    MatchState m = test::match(RuleSet::Icf);
    StrokePhysics physics = test::pocketing(m, {}, true);
    physics.striker_touched_coin = false;
    const StrokeResult r = judge_stroke(m, 0, Shot{}, physics);
    EXPECT_EQ(r.state.dues_owed[0], 0);
    EXPECT_EQ(r.state.turn_seat, 0);
}

TEST(RulesIcf, DuesDoNotCarryToTheNextBoard) {
    MatchState m = with_all_but(broken(RuleSet::Icf), BodyKind::White, kWhite, 0);
    m.dues_owed = {0, 2};
    const MatchState next = start_next_board(stroke(m, {kWhite}).state);
    EXPECT_EQ(next.dues_owed, (std::vector<int>{0, 0}));
}

} // namespace
} // namespace carrom::rules
