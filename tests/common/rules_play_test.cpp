// Rules cases produced by real strokes through the exact engine: positions and velocities are
// chosen so that the physics makes the case (see rules_support.hpp, kNearPocket).

#include "rules_support.hpp"

#include <gtest/gtest.h>

namespace carrom::rules {
namespace {

using test::kBlack;
using test::kHard;
using test::kNearPocket;
using test::kSoft;
using test::kWhite;
using test::kWhite2;
using test::play;
using test::pre_pocket;
using test::put;
using test::towards_pocket;

TEST(RulesPlay, OwnCoinDropsAndTheShooterGoesAgain) {
    MatchState m = test::match(RuleSet::Icf);
    put(m, kWhite, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    ASSERT_FALSE(r.error.has_value()) << r.error->message;
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kWhite}));
    EXPECT_FALSE(r.outcome.striker_pocketed);
    EXPECT_TRUE(r.state.break_done); // the striker touched a coin
    EXPECT_TRUE(r.outcome.extra_stroke);
    EXPECT_TRUE(r.outcome.shot_taken);
    EXPECT_FALSE(r.outcome.physics.events.empty());
    EXPECT_EQ(r.state.turn_number, 1);
}

TEST(RulesPlay, StrikerWithOwnCoinReturnsItOwesADueAndShootsAgain) {
    MatchState m = test::broken(RuleSet::Icf);
    put(m, kWhite, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kHard));
    ASSERT_FALSE(r.error.has_value());
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kWhite}));
    EXPECT_TRUE(r.outcome.striker_pocketed);
    ASSERT_EQ(r.outcome.returned.size(), 1u);
    EXPECT_EQ(r.outcome.returned[0].id, kWhite);
    EXPECT_EQ(r.state.dues_owed[0], 1);
    EXPECT_TRUE(r.outcome.extra_stroke);
    EXPECT_FALSE(test::overlaps_any(r.state));
}

TEST(RulesPlay, DueOwedThenPaid) {
    MatchState m = test::broken(RuleSet::Icf);
    PlayResult r = play(m, towards_pocket(m, 0, kHard)); // the striker alone
    ASSERT_TRUE(r.outcome.striker_pocketed);
    EXPECT_TRUE(r.outcome.pocketed.empty());
    EXPECT_EQ(r.state.dues_owed[0], 1);
    r = play(r.state, test::miss()); // seat 1
    EXPECT_EQ(r.state.turn_seat, 0);
    m = r.state;
    put(m, kWhite, kNearPocket);
    r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kWhite}));
    EXPECT_EQ(r.outcome.dues_paid, 1);
    EXPECT_EQ(r.state.dues_owed[0], 0);
    EXPECT_FALSE(r.state.bodies[kWhite].pocketed);
}

TEST(RulesPlay, QueenThenCoverOnTheNextStroke) {
    MatchState m = test::broken(RuleSet::Icf);
    pre_pocket(m, 6, 0);
    put(m, kQueenId, kNearPocket);
    PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kQueenId}));
    EXPECT_EQ(r.state.queen.status, QueenStatus::PendingCover);
    ASSERT_EQ(r.state.turn_seat, 0);
    m = r.state;
    put(m, kWhite, kNearPocket);
    r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kWhite}));
    EXPECT_EQ(r.state.queen.status, QueenStatus::Covered);
    EXPECT_EQ(r.state.queen.seat, 0);
}

TEST(RulesPlay, QueenUncoveredGoesBackToTheCentre) {
    MatchState m = test::broken(RuleSet::Icf);
    pre_pocket(m, 6, 0);
    put(m, kQueenId, kNearPocket);
    PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    ASSERT_EQ(r.state.queen.status, QueenStatus::PendingCover);
    r = play(r.state, test::miss());
    EXPECT_EQ(r.state.queen.status, QueenStatus::OnBoard);
    EXPECT_EQ(r.state.bodies[kQueenId].pos_px, (Vec2{300.0, 300.0}));
    EXPECT_EQ(r.state.turn_seat, 1);
}

TEST(RulesPlay, OwnLastCoinBeforeTheQueen) {
    MatchState m = test::broken(RuleSet::Icf);
    for (int id : test::ids_of(m, BodyKind::White)) {
        if (id != kWhite) {
            pre_pocket(m, id, 0);
        }
    }
    put(m, kWhite, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    ASSERT_TRUE(r.outcome.board_end.has_value());
    EXPECT_EQ(r.outcome.board_end->reason, RuleCode::OwnLastCoinBeforeQueen);
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 3}));
}

TEST(RulesPlay, OpponentsLastCoin) {
    MatchState m = test::broken(RuleSet::Icf);
    for (int id : test::ids_of(m, BodyKind::Black)) {
        if (id != kBlack) {
            pre_pocket(m, id, 1);
        }
    }
    pre_pocket(m, kWhite2, 0);
    put(m, kBlack, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    ASSERT_TRUE(r.outcome.board_end.has_value());
    EXPECT_EQ(r.outcome.board_end->reason, RuleCode::OpponentLastCoin);
    EXPECT_EQ(r.state.scores, (std::vector<int>{0, 3 + 8}));
}

TEST(RulesPlay, TopSeatShootsFromTheTop) {
    MatchState m = test::broken(RuleSet::Icf);
    m.turn_seat = 1;
    put(m, kBlack, test::kNearPocketTop);
    const PlayResult r = play(m, towards_pocket(m, 1, kSoft));
    ASSERT_FALSE(r.error.has_value());
    EXPECT_EQ(r.outcome.pocketed, (std::vector<int>{kBlack}));
    EXPECT_EQ(r.state.turn_seat, 1);
}

// Each rule set's end of game, from a real stroke.
TEST(RulesPlay, IcfGameEndsOnTheTarget) {
    MatchState m = test::broken(RuleSet::Icf);
    for (int id : test::ids_of(m, BodyKind::White)) {
        if (id != kWhite) {
            pre_pocket(m, id, 0);
        }
    }
    pre_pocket(m, kQueenId, 0);
    m.queen = QueenState{QueenStatus::Covered, 0};
    m.scores = {14, 3};
    put(m, kWhite, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.state.scores, (std::vector<int>{26, 3}));
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.state.result->winner_team, 0);
}

TEST(RulesPlay, SeedGameEndsWhenBlackIsCleared) {
    MatchState m = test::match(RuleSet::Seed);
    for (int id : test::ids_of(m, BodyKind::Black)) {
        if (id != kBlack) {
            pre_pocket(m, id, 0);
        }
    }
    m.scores = {8, 0};
    put(m, kBlack, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.state.result->winner_team, 0);
    EXPECT_EQ(r.state.result->reason, RuleCode::ColourCleared);
}

TEST(RulesPlay, FreestyleGameEndsAtTheTarget) {
    MatchState m = test::match(RuleSet::Freestyle);
    m.scores = {155, 0};
    put(m, kWhite, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.state.scores, (std::vector<int>{175, 0}));
    EXPECT_EQ(r.state.result->reason, RuleCode::TargetPoints);
}

TEST(RulesPlay, DiscPoolGameEndsWhenOwnCoinsAreCleared) {
    MatchState m = test::match(RuleSet::DiscPool);
    for (int id : test::ids_of(m, BodyKind::White)) {
        if (id != kWhite) {
            pre_pocket(m, id, 0);
        }
    }
    put(m, kWhite, kNearPocket);
    const PlayResult r = play(m, towards_pocket(m, 0, kSoft));
    EXPECT_EQ(r.state.phase, Phase::GameOver);
    EXPECT_EQ(r.state.result->winner_team, 0);
    EXPECT_EQ(r.state.scores, (std::vector<int>{9, 0}));
}

TEST(RulesPlay, TrajectoryOnRequest) {
    MatchState m = test::match(RuleSet::Icf);
    ExactEngine engine(m.physics);
    const PlayResult without = play_shot(m, 0, Shot{300.0, -1.5, 10.0}, engine);
    EXPECT_TRUE(without.outcome.physics.trajectory.segments.empty());
    const PlayResult with = play_shot(m, 0, Shot{300.0, -1.5, 10.0}, engine, {true});
    EXPECT_FALSE(with.outcome.physics.trajectory.segments.empty());
    EXPECT_EQ(with.outcome.pocketed, without.outcome.pocketed);
}

} // namespace
} // namespace carrom::rules
