// hash_match_state: equal states hash equal; every kind of field counts, to the last bit. The
// hash of a new match is pinned because match journals store these values: a change to it
// needs a kRulesVersion bump (carrom/rules/rules_version.hpp).

#include "carrom/rules/state_hash.hpp"

#include "carrom/rules/match.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace carrom::rules {
namespace {

MatchState fresh(RuleSet rule_set = RuleSet::Icf) {
    return new_match(rule_set, RulesConfig{}, PhysicsConfig{});
}

TEST(StateHash, ANewIcfMatchHasThePinnedHash) {
    EXPECT_EQ(hash_match_state(fresh()), 0x5600ddc946612ab2ULL)
        << std::hex << "actual 0x" << hash_match_state(fresh());
}

TEST(StateHash, EqualStatesHashEqual) {
    const MatchState a = fresh();
    const MatchState b = fresh();
    EXPECT_EQ(hash_match_state(a), hash_match_state(b));
}

TEST(StateHash, RuleSetsDiffer) {
    EXPECT_NE(hash_match_state(fresh(RuleSet::Icf)), hash_match_state(fresh(RuleSet::Seed)));
    EXPECT_NE(hash_match_state(fresh(RuleSet::Freestyle)),
              hash_match_state(fresh(RuleSet::DiscPool)));
}

TEST(StateHash, TheLastBitOfAPositionCounts) {
    const MatchState a = fresh();
    MatchState b = a;
    b.bodies[5].pos_px.x = std::nextafter(b.bodies[5].pos_px.x, 1000.0);
    EXPECT_NE(hash_match_state(a), hash_match_state(b));
}

TEST(StateHash, NegativeZeroDiffersFromZero) {
    MatchState a = fresh();
    a.bodies[3].vel_px_s.x = 0.0;
    MatchState b = a;
    b.bodies[3].vel_px_s.x = -0.0;
    EXPECT_NE(hash_match_state(a), hash_match_state(b));
}

TEST(StateHash, CountersQueenAndPhaseCount) {
    const std::uint64_t base = hash_match_state(fresh());
    MatchState m = fresh();
    m.turn_number = 1;
    EXPECT_NE(hash_match_state(m), base);
    m = fresh();
    m.scores[1] = 3;
    EXPECT_NE(hash_match_state(m), base);
    m = fresh();
    m.dues_owed[0] = 1;
    EXPECT_NE(hash_match_state(m), base);
    m = fresh();
    m.queen.seat = 1;
    EXPECT_NE(hash_match_state(m), base);
    m = fresh();
    m.phase = Phase::BoardOver;
    EXPECT_NE(hash_match_state(m), base);
    m = fresh();
    m.break_done = true;
    EXPECT_NE(hash_match_state(m), base);
}

TEST(StateHash, PocketedListAndResultsCount) {
    MatchState a = fresh();
    a.bodies[4].pocketed = true;
    a.pocketed.push_back(PocketedPiece{4, a.bodies[4].kind, 0, 0});
    MatchState b = a;
    b.pocketed[0].seat = 1;
    EXPECT_NE(hash_match_state(a), hash_match_state(b));

    MatchState won = fresh();
    won.result = GameResult{0, RuleCode::TargetPoints};
    MatchState drawn = fresh();
    drawn.result = GameResult{std::nullopt, RuleCode::TargetPoints};
    EXPECT_NE(hash_match_state(won), hash_match_state(drawn));
    EXPECT_NE(hash_match_state(won), hash_match_state(fresh()));
}

TEST(StateHash, BothConfigsCount) {
    RulesConfig rules;
    rules.shot_clock_s = 30.0;
    PhysicsConfig physics;
    const std::uint64_t base = hash_match_state(fresh());
    EXPECT_NE(hash_match_state(new_match(RuleSet::Icf, rules, physics)), base);
    physics.damping_per_s = std::nextafter(physics.damping_per_s, 2.0);
    EXPECT_NE(hash_match_state(new_match(RuleSet::Icf, RulesConfig{}, physics)), base);
}

// Lists are hashed with their lengths: moving a value from one list to the next changes it.
TEST(StateHash, ListBoundariesCount) {
    MatchState a = fresh();
    a.scores = {1, 2};
    a.dues_owed = {0};
    MatchState b = a;
    b.scores = {1};
    b.dues_owed = {2, 0};
    EXPECT_NE(hash_match_state(a), hash_match_state(b));
}

} // namespace
} // namespace carrom::rules
