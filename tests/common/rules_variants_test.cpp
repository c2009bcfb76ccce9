// seed, freestyle and discpool rules, judged from chosen pocketed sets (no physics).

#include "rules_support.hpp"

#include <gtest/gtest.h>

namespace carrom::rules {
namespace {

using test::ids_of;
using test::kBlack;
using test::kBlack2;
using test::kWhite;
using test::kWhite2;
using test::pre_pocket;
using test::stroke;

// ---- seed -------------------------------------------------------------------------------------

TEST(RulesSeed, PlayerOnePlaysBlackFromTheBottom) {
    const MatchState m = test::match(RuleSet::Seed);
    EXPECT_EQ(team_colour(m, 0), BodyKind::Black);
    EXPECT_EQ(team_colour(m, 1), BodyKind::White);
    EXPECT_EQ(m.seats[0].side, Side::Bottom);
    EXPECT_EQ(m.turn_seat, 0);
}

TEST(RulesSeed, EachColourScoresForItsOwnerWhoeverPocketsIt) {
    const StrokeResult r = stroke(test::match(RuleSet::Seed), {kBlack, kWhite, kWhite2});
    EXPECT_EQ(r.state.scores, (std::vector<int>{1, 2}));
    EXPECT_EQ(r.outcome.score_changes, (std::vector<int>{1, 2}));
    EXPECT_TRUE(r.outcome.extra_stroke); // an own (black) coin went in
}

TEST(RulesSeed, OnlyOpponentCoinsPassTheTurn) {
    const StrokeResult r = stroke(test::match(RuleSet::Seed), {kWhite});
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 1}));
}

TEST(RulesSeed, StrikerReturnsTheShootersLastPocketedCoin) {
    MatchState m = test::match(RuleSet::Seed);
    m = stroke(m, {kBlack}).state;
    m = stroke(m, {kBlack2}).state;
    const StrokeResult r = stroke(m, {}, true);
    ASSERT_EQ(r.outcome.returned.size(), 1u);
    EXPECT_EQ(r.outcome.returned[0].id, kBlack2);
    EXPECT_EQ(r.state.scores, (std::vector<int>{1, 0}));
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_EQ(r.state.dues_owed, (std::vector<int>{0, 0})); // the seed has no dues
}

TEST(RulesSeed, StrikerWithNothingPocketedReturnsNothing) {
    const StrokeResult r = stroke(test::match(RuleSet::Seed), {}, true);
    EXPECT_TRUE(r.outcome.returned.empty());
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 0}));
    EXPECT_EQ(r.outcome.fouls.size(), 1u);
}

TEST(RulesSeed, QueenIsCoveredOnTheNextStrokeForThreePoints) {
    const StrokeResult first = stroke(test::match(RuleSet::Seed), {kQueenId});
    EXPECT_EQ(first.state.queen.status, QueenStatus::PendingCover);
    EXPECT_TRUE(first.outcome.extra_stroke); // fixed: the seed passed the turn here
    const StrokeResult second = stroke(first.state, {kBlack});
    EXPECT_EQ(second.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(second.state.scores, (std::vector<int>{1 + 3, 0}));
}

TEST(RulesSeed, QueenUncoveredReturnsToTheCentre) {
    const StrokeResult first = stroke(test::match(RuleSet::Seed), {kQueenId});
    const StrokeResult second = stroke(first.state, {});
    EXPECT_EQ(second.state.queen.status, QueenStatus::OnBoard);
    ASSERT_EQ(second.outcome.returned.size(), 1u);
    EXPECT_EQ(second.outcome.returned[0].pos_px, (Vec2{300.0, 300.0}));
    EXPECT_EQ(second.state.scores, (std::vector<int>{0, 0}));
}

TEST(RulesSeed, QueenWithOwnCoinInTheSameStrokeIsCovered) {
    const StrokeResult r = stroke(test::match(RuleSet::Seed), {kQueenId, kBlack});
    EXPECT_EQ(r.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(r.state.scores, (std::vector<int>{4, 0}));
}

TEST(RulesSeed, GameEndsWhenAColourIsClearedAndTheHigherScoreWins) {
    MatchState m = test::match(RuleSet::Seed);
    for (int id : ids_of(m, BodyKind::White)) {
        if (id != kWhite) {
            pre_pocket(m, id, 1);
        }
    }
    m.scores = {3, 8};
    m.turn_seat = 1;
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    ASSERT_TRUE(r.outcome.game_end.has_value());
    EXPECT_EQ(r.outcome.game_end->winner_team, 1);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::ColourCleared);
    EXPECT_TRUE(r.outcome.board_end.has_value());
}

TEST(RulesSeed, TiedScoresGoToTheSideWhoseColourWasCleared) {
    MatchState m = test::match(RuleSet::Seed);
    for (int id : ids_of(m, BodyKind::White)) {
        if (id != kWhite) {
            pre_pocket(m, id, 0);
        }
    }
    m.scores = {9, 8};
    const StrokeResult r = stroke(m, {kWhite}); // seat 0 pockets white's last coin: 9 - 9
    EXPECT_EQ(r.state.scores, (std::vector<int>{9, 9}));
    EXPECT_EQ(r.outcome.game_end->winner_team, 1);
}

TEST(RulesSeed, AFoulIsAppliedBeforeTheEndOfGameCheck) {
    MatchState m = test::match(RuleSet::Seed);
    for (int id : ids_of(m, BodyKind::Black)) {
        if (id != kBlack) {
            pre_pocket(m, id, 0);
        }
    }
    m.scores = {8, 0};
    const StrokeResult r = stroke(m, {kBlack}, true); // the coin comes straight back
    EXPECT_EQ(r.state.phase, Phase::AwaitingShot);
    EXPECT_EQ(count_on_board(r.state, BodyKind::Black), 1);
    EXPECT_EQ(r.state.scores, (std::vector<int>{8, 0}));
}

// ---- freestyle --------------------------------------------------------------------------------

TEST(RulesFreestyle, AnyCoinScoresForTheShooter) {
    const StrokeResult r = stroke(test::match(RuleSet::Freestyle), {kWhite, kBlack});
    EXPECT_EQ(r.state.scores, (std::vector<int>{30, 0}));
    EXPECT_TRUE(r.outcome.extra_stroke);
    MatchState m = r.state;
    m = stroke(m, {}).state;
    EXPECT_EQ(m.turn_seat, 1);
    EXPECT_EQ(stroke(m, {kWhite2}).state.scores, (std::vector<int>{30, 20}));
}

TEST(RulesFreestyle, StrikerCostsPointsAndTheTurnButCoinsCount) {
    const StrokeResult r = stroke(test::match(RuleSet::Freestyle), {kBlack}, true);
    EXPECT_EQ(r.state.scores, (std::vector<int>{10 - 20, 0}));
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_TRUE(r.state.bodies[kBlack].pocketed);
    EXPECT_EQ(r.outcome.fouls[0].code, RuleCode::StrikerPocketed);
}

TEST(RulesFreestyle, QueenCoveredByAnyCoinOnTheNextStrokeScoresFifty) {
    const StrokeResult first = stroke(test::match(RuleSet::Freestyle), {kQueenId});
    EXPECT_EQ(first.state.queen.status, QueenStatus::PendingCover);
    EXPECT_EQ(first.state.scores, (std::vector<int>{0, 0}));
    EXPECT_TRUE(first.outcome.extra_stroke);
    const StrokeResult second = stroke(first.state, {kBlack});
    EXPECT_EQ(second.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(second.state.scores, (std::vector<int>{60, 0}));
}

TEST(RulesFreestyle, QueenUncoveredReturns) {
    const StrokeResult first = stroke(test::match(RuleSet::Freestyle), {kQueenId});
    const StrokeResult second = stroke(first.state, {});
    EXPECT_EQ(second.state.queen.status, QueenStatus::OnBoard);
    EXPECT_EQ(second.state.scores, (std::vector<int>{0, 0}));
    EXPECT_EQ(second.state.turn_seat, 1);
}

TEST(RulesFreestyle, FirstToTheTargetWins) {
    MatchState m = test::match(RuleSet::Freestyle);
    m.scores = {150, 160};
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.outcome.game_end->winner_team, 0);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::TargetPoints);
}

MatchState freestyle_down_to(const std::vector<int>& left) {
    MatchState m = test::match(RuleSet::Freestyle);
    for (int id = 1; id <= 18; ++id) {
        if (!test::contains_id(left, id)) {
            pre_pocket(m, id, 0);
        }
    }
    return m;
}

TEST(RulesFreestyle, WhenTheCoinsRunOutTheHigherScoreWins) {
    MatchState m = freestyle_down_to({kBlack});
    m.scores = {100, 95};
    m.turn_seat = 1;
    const StrokeResult r = stroke(m, {kBlack});
    EXPECT_EQ(r.state.scores, (std::vector<int>{100, 105}));
    EXPECT_EQ(r.outcome.game_end->winner_team, 1);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::CoinsExhausted);
}

TEST(RulesFreestyle, EqualScoresWhenTheCoinsRunOutAreADraw) {
    MatchState m = freestyle_down_to({kBlack});
    m.scores = {100, 90};
    m.turn_seat = 1;
    const StrokeResult r = stroke(m, {kBlack});
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_FALSE(r.outcome.game_end->winner_team.has_value());
}

TEST(RulesFreestyle, LastCoinCoversAQueenPocketedWithIt) {
    MatchState m = freestyle_down_to({kBlack});
    const StrokeResult r = stroke(m, {kQueenId, kBlack});
    EXPECT_EQ(r.state.scores, (std::vector<int>{60, 0}));
    EXPECT_EQ(r.state.phase, Phase::GameOver);
}

// ---- discpool ---------------------------------------------------------------------------------

TEST(RulesDiscPool, NoQueenAndTheBreakerOwnsWhite) {
    const MatchState m = test::match(RuleSet::DiscPool);
    EXPECT_EQ(m.queen.status, QueenStatus::OutOfPlay);
    EXPECT_TRUE(m.bodies[kQueenId].pocketed);
    EXPECT_EQ(team_colour(m, 0), BodyKind::White);
}

TEST(RulesDiscPool, OwnCoinKeepsTheTurnOpponentCoinPassesIt) {
    const StrokeResult own = stroke(test::match(RuleSet::DiscPool), {kWhite});
    EXPECT_TRUE(own.outcome.extra_stroke);
    EXPECT_EQ(own.state.scores, (std::vector<int>{1, 0}));
    const StrokeResult opp = stroke(own.state, {kBlack});
    EXPECT_EQ(opp.state.turn_seat, 1);
    EXPECT_EQ(opp.state.scores, (std::vector<int>{1, 1}));
}

TEST(RulesDiscPool, StrikerReturnsOwnCoinsAndCostsADue) {
    MatchState m = test::match(RuleSet::DiscPool);
    pre_pocket(m, 6, 0);
    const StrokeResult r = stroke(m, {kWhite, kBlack}, true);
    EXPECT_EQ(count_on_board(r.state, BodyKind::White), 9); // kWhite back, 6 paid as the due
    EXPECT_TRUE(r.state.bodies[kBlack].pocketed);
    EXPECT_EQ(r.state.turn_seat, 1);
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 1}));
}

TEST(RulesDiscPool, ClearingYourOwnCoinsWins) {
    MatchState m = test::match(RuleSet::DiscPool);
    for (int id : ids_of(m, BodyKind::White)) {
        if (id != kWhite) {
            pre_pocket(m, id, 0);
        }
    }
    const StrokeResult r = stroke(m, {kWhite});
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.outcome.game_end->winner_team, 0);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::BoardCleared);
}

TEST(RulesDiscPool, PocketingTheOpponentsLastCoinMakesThemWin) {
    MatchState m = test::match(RuleSet::DiscPool);
    for (int id : ids_of(m, BodyKind::Black)) {
        if (id != kBlack) {
            pre_pocket(m, id, 1);
        }
    }
    const StrokeResult r = stroke(m, {kBlack});
    EXPECT_EQ(r.outcome.game_end->winner_team, 1);
    EXPECT_EQ(r.outcome.game_end->reason, RuleCode::OpponentLastCoin);
}

} // namespace
} // namespace carrom::rules
