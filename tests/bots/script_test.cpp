#include "carrom/bots/scripted_strategy.hpp"

#include "carrom/bots/shot_geometry.hpp"
#include "carrom/rules/match.hpp"

#include <gtest/gtest.h>

namespace carrom::bots {
namespace {

std::vector<Shot> shots_of(std::string_view text) {
    auto parsed = parse_script(text);
    EXPECT_TRUE(std::holds_alternative<std::vector<Shot>>(parsed)) << std::get<std::string>(parsed);
    return std::holds_alternative<std::vector<Shot>>(parsed) ? std::get<std::vector<Shot>>(parsed)
                                                             : std::vector<Shot>{};
}

std::string error_of(std::string_view text) {
    auto parsed = parse_script(text);
    EXPECT_TRUE(std::holds_alternative<std::string>(parsed));
    return std::holds_alternative<std::string>(parsed) ? std::get<std::string>(parsed) : "";
}

rules::MatchState icf_match() {
    return rules::new_match(rules::RuleSet::Icf, rules::RulesConfig{}, PhysicsConfig{});
}

TEST(Script, ParsesLinesSkippingBlanksAndComments) {
    const auto shots = shots_of("# opening\n{\"x\": 300, \"angle\": -1.5, \"power\": 20}\n\n"
                                "  \r\n{\"x\":150.5,\"angle\":-2,\"power\":0,\"note\":1}\r\n");
    ASSERT_EQ(shots.size(), 2u);
    EXPECT_DOUBLE_EQ(shots[0].x_px, 300.0);
    EXPECT_DOUBLE_EQ(shots[0].angle_rad, -1.5);
    EXPECT_DOUBLE_EQ(shots[0].power, 20.0);
    EXPECT_DOUBLE_EQ(shots[1].x_px, 150.5);
    EXPECT_DOUBLE_EQ(shots[1].power, 0.0);
}

TEST(Script, LastLineWithoutNewline) {
    EXPECT_EQ(shots_of("{\"x\":300,\"angle\":0,\"power\":1}").size(), 1u);
}

TEST(Script, ErrorsNameTheLineAndTheField) {
    EXPECT_EQ(error_of("\n{\"x\":300,\"angle\":0}\n"), "line 2: missing field 'power'.");
    EXPECT_EQ(error_of("{\"x\":\"300\",\"angle\":0,\"power\":1}"),
              "line 1: field 'x' must be a number.");
    EXPECT_EQ(error_of("{\"x\":300,\"angle\":0,\"power\":26}"),
              "line 1: field 'power' must be a number in [0.000000, 25.000000].");
    EXPECT_EQ(error_of("{\"x\":300,\"angle\":0,\"power\":1e400}"), "line 1: not valid JSON.");
    EXPECT_EQ(error_of("[300, 0, 1]"),
              "line 1: must be a JSON object {\"x\", \"angle\", \"power\"}.");
    EXPECT_EQ(error_of("{\"x\":-1,\"angle\":0,\"power\":1}"),
              "line 1: field 'x' must be a number in [0.000000, 10000.000000].");
    EXPECT_EQ(error_of("{\"x\":300,\"angle\":NaN,\"power\":1}"), "line 1: not valid JSON.");
}

TEST(Script, EmptyScriptIsAnError) {
    EXPECT_EQ(error_of(""), "The script has no shots.");
    EXPECT_EQ(error_of("# nothing\n\n"), "The script has no shots.");
}

TEST(ScriptedStrategy, PlaysShotsInOrderAndStartsAgain) {
    const auto state = icf_match();
    ScriptedStrategy strategy({{200, -1.0, 10}, {400, -2.0, 20}});
    const DecisionBudget budget;
    EXPECT_DOUBLE_EQ(strategy.choose_shot(state, 0, budget).x_px, 200.0);
    EXPECT_DOUBLE_EQ(strategy.choose_shot(state, 0, budget).angle_rad, -2.0);
    EXPECT_DOUBLE_EQ(strategy.choose_shot(state, 0, budget).power, 10.0);
}

TEST(ScriptedStrategy, BlockedPositionMovesToTheNearestLegalOne) {
    auto state = icf_match();
    // A coin sitting on the bottom baseline at x = 300 blocks the striker there.
    state.bodies[1].pos_px = {300.0, baseline_y(state.physics, Baseline::Bottom)};
    ScriptedStrategy strategy({{300, -1.5, 10}});
    const Shot shot = strategy.choose_shot(state, 0, DecisionBudget{});
    EXPECT_TRUE(shot_is_legal(state, 0, shot));
    // Striker 18 + coin 14 = 32 px apart at least.
    EXPECT_NEAR(std::abs(shot.x_px - 300.0), 32.0, 0.6);
    EXPECT_DOUBLE_EQ(shot.angle_rad, -1.5);
}

TEST(ScriptedStrategy, RefusedShotIsRetriedMoved) {
    const auto state = icf_match();
    ScriptedStrategy strategy({{200, -1.0, 10}, {400, -2.0, 20}});
    EXPECT_DOUBLE_EQ(strategy.choose_shot(state, 0, DecisionBudget{}).x_px, 200.0);
    strategy.shot_refused();
    EXPECT_DOUBLE_EQ(strategy.choose_shot(state, 0, DecisionBudget{}).x_px, 203.0);
    EXPECT_DOUBLE_EQ(strategy.choose_shot(state, 0, DecisionBudget{}).x_px, 400.0);
}

} // namespace
} // namespace carrom::bots
