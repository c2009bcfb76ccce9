#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/sampling_strategy.hpp"
#include "carrom/bots/shot_geometry.hpp"
#include "carrom/bots/shot_score.hpp"
#include "carrom/rules/match.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace carrom::bots {
namespace {

rules::MatchState match_with_defaults(rules::RuleSet rule_set) {
    return rules::new_match(rule_set, rules::RulesConfig{}, PhysicsConfig{});
}

TEST(ShotGeometry, ForwardIsUpForBottomAndDownForTop) {
    const auto state = match_with_defaults(rules::RuleSet::Icf);
    EXPECT_DOUBLE_EQ(forward_angle(state, 0), -std::numbers::pi / 2.0);
    EXPECT_DOUBLE_EQ(forward_angle(state, 1), std::numbers::pi / 2.0);
}

TEST(ShotGeometry, NearestLegalXIsTheSameWhenFree) {
    const auto state = match_with_defaults(rules::RuleSet::Icf);
    EXPECT_DOUBLE_EQ(*nearest_legal_x(state, 0, 300.0), 300.0);
    const auto range = baseline_range(state);
    EXPECT_DOUBLE_EQ(*nearest_legal_x(state, 0, 0.0), range.min_px);
    EXPECT_DOUBLE_EQ(*nearest_legal_x(state, 1, 1e9), range.max_px);
}

TEST(RandomStrategy, ShotsAreLegalAndAimedIntoTheBoard) {
    for (const int seat : {0, 1}) {
        auto state = match_with_defaults(rules::RuleSet::Icf);
        state.turn_seat = seat;
        RandomStrategy strategy(7);
        for (int i = 0; i < 200; ++i) {
            const Shot shot = strategy.choose_shot(state, seat, DecisionBudget{});
            EXPECT_TRUE(shot_is_legal(state, seat, shot));
            const double off = std::abs(shot.angle_rad - forward_angle(state, seat));
            EXPECT_LE(off, 75.0 * std::numbers::pi / 180.0 + 1e-12);
            EXPECT_GE(shot.power, 0.35 * state.physics.max_power);
            EXPECT_LE(shot.power, state.physics.max_power);
        }
    }
}

TEST(RandomStrategy, SameSeedSameShots) {
    const auto state = match_with_defaults(rules::RuleSet::Freestyle);
    RandomStrategy a(99);
    RandomStrategy b(99);
    RandomStrategy c(100);
    int differ = 0;
    for (int i = 0; i < 20; ++i) {
        const Shot sa = a.choose_shot(state, 0, DecisionBudget{});
        const Shot sb = b.choose_shot(state, 0, DecisionBudget{});
        const Shot sc = c.choose_shot(state, 0, DecisionBudget{});
        EXPECT_EQ(sa.x_px, sb.x_px);
        EXPECT_EQ(sa.angle_rad, sb.angle_rad);
        EXPECT_EQ(sa.power, sb.power);
        differ += sa.x_px != sc.x_px ? 1 : 0;
    }
    EXPECT_GT(differ, 15);
}

TEST(ShotScore, OwnCoinsCountForAndFoulsAgainst) {
    const auto before = match_with_defaults(rules::RuleSet::Freestyle);
    rules::PlayResult result;
    result.state = before;
    result.outcome.seat = 0;
    result.outcome.pocketed = {1, 2}; // any coin scores in freestyle
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 0), 20.0);
    result.outcome.fouls.push_back({rules::RuleCode::StrikerPocketed, 0});
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 0), -10.0);
    result.outcome.score_changes = {30, 0};
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 0), 140.0);
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 1), -160.0 + 0.0);
}

TEST(ShotScore, OpponentColourCountsAgainst) {
    const auto before = match_with_defaults(rules::RuleSet::Seed); // team 0 black, team 1 white
    rules::PlayResult result;
    result.state = before;
    int black = -1;
    int white = -1;
    for (const Body& body : before.bodies) {
        if (body.kind == BodyKind::Black && black < 0) {
            black = body.id;
        }
        if (body.kind == BodyKind::White && white < 0) {
            white = body.id;
        }
    }
    result.outcome.pocketed = {black};
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 0), 10.0);
    result.outcome.pocketed = {white};
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 0), -6.0);
}

TEST(ShotScore, WinningTheGameDominates) {
    const auto before = match_with_defaults(rules::RuleSet::Icf);
    rules::PlayResult result;
    result.state = before;
    result.outcome.game_end = rules::GameResult{1, rules::RuleCode::BoardCleared};
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 1), 1000.0);
    EXPECT_DOUBLE_EQ(score_outcome(before, result, 0), -1000.0);
}

TEST(SamplingStrategy, PicksTheBestOfItsCandidates) {
    const auto state = match_with_defaults(rules::RuleSet::Freestyle);
    SamplingStrategy sampling(5, 24);
    DecisionBudget budget;
    budget.time = std::chrono::seconds(30); // the candidate count ends the search
    const Shot chosen = sampling.choose_shot(state, 0, budget);
    EXPECT_EQ(sampling.last_candidates(), 24);
    EXPECT_TRUE(shot_is_legal(state, 0, chosen));
    // Replaying the same candidates: none scores better than the chosen one.
    ExactEngine engine(state.physics);
    const double chosen_score = score_outcome(state, rules::play_shot(state, 0, chosen, engine), 0);
    RandomStrategy same_draws(5);
    for (int i = 0; i < 24; ++i) {
        const Shot candidate = same_draws.choose_shot(state, 0, budget);
        const auto result = rules::play_shot(state, 0, candidate, engine);
        ASSERT_FALSE(result.error);
        EXPECT_LE(score_outcome(state, result, 0), chosen_score);
    }
}

TEST(SamplingStrategy, CandidateLimitOfTheBudgetIsHonoured) {
    const auto state = match_with_defaults(rules::RuleSet::Icf);
    SamplingStrategy sampling(1, 100);
    DecisionBudget budget;
    budget.time = std::chrono::seconds(30);
    budget.max_candidates = 3;
    sampling.choose_shot(state, 0, budget);
    EXPECT_EQ(sampling.last_candidates(), 3);
}

TEST(MakeStrategy, KnownNamesAndAClearErrorOtherwise) {
    StrategyOptions options;
    for (const auto& name : {"random", "sampling"}) {
        options.name = name;
        auto made = make_strategy(options);
        ASSERT_TRUE(std::holds_alternative<std::unique_ptr<Strategy>>(made));
        EXPECT_EQ(std::get<std::unique_ptr<Strategy>>(made)->name(), name);
    }
    options.name = "scripted";
    EXPECT_EQ(std::get<std::string>(make_strategy(options)),
              "The scripted strategy needs a script with at least one shot.");
    options.script = {Shot{}};
    EXPECT_TRUE(std::holds_alternative<std::unique_ptr<Strategy>>(make_strategy(options)));
    options.name = "genius";
    EXPECT_EQ(std::get<std::string>(make_strategy(options)),
              "Unknown strategy 'genius' (known: random, scripted, sampling, greedy).");
}

// The protocol's bot levels: random plays at random, the others search (the greedy strategy).
TEST(MakeStrategy, BotLevelsOfTheProtocol) {
    EXPECT_EQ(make_level_strategy(proto::BotLevel::Random, 1)->name(), "random");
    for (auto level : {proto::BotLevel::Easy, proto::BotLevel::Medium, proto::BotLevel::Hard}) {
        EXPECT_EQ(make_level_strategy(level, 1)->name(), "greedy");
    }
}

} // namespace
} // namespace carrom::bots
