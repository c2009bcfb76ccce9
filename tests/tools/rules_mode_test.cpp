// `carrom-sim --rules` end to end: a match state plus a shot in, the outcome and new state out;
// bad input and refused moves give {"error": {...}} on stderr and exit code 2.

#include "support/command_run.hpp"
#include "support/read_file.hpp"
#include "tools/sim_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace {

using Json = nlohmann::json;

struct RulesRun {
    int exit_code = -1;
    Json out;
    Json err;
};

using carrom::sim_testing::temp_path;

RulesRun run_rules(const Json& input) {
    const std::string in_path = temp_path("in.json");
    const std::string err_path = temp_path("err.txt");
    std::ofstream(in_path, std::ios::binary) << input.dump();
    const std::string command =
        std::string(CARROM_SIM_PATH) + " --rules < " + in_path + " 2>" + err_path;
    const carrom::test_support::CommandRun ran = carrom::test_support::run_command(command);
    RulesRun run;
    run.exit_code = ran.exit;
    run.out = Json::parse(ran.out, nullptr, false);
    run.err = Json::parse(carrom::test_support::read_file(err_path), nullptr, false);
    return run;
}

// White coin 2 just off the bottom-right pocket; a soft shot from x = 487 drops it.
Json coin_near_pocket_state() {
    Json bodies = Json::array();
    bodies.push_back({{"id", 0}, {"kind", "queen"}, {"pos", {300.0, 300.0}}});
    for (int id = 1; id <= 18; ++id) {
        const double x = 100.0 + 20.0 * (id % 10) * 1.6;
        const double y = id <= 9 ? 200.0 : 400.0;
        bodies.push_back({{"id", id}, {"kind", id % 2 == 1 ? "black" : "white"}, {"pos", {x, y}}});
    }
    bodies[2]["pos"] = {518.5, 533.0};
    return {{"rule_set", "icf"}, {"bodies", bodies}, {"break_done", true}};
}

TEST(RulesMode, AShotGivesTheOutcomeAndTheNextState) {
    const double angle = std::atan2(543.0 - 520.0, 543.0 - 487.0);
    const RulesRun run = run_rules({{"state", coin_near_pocket_state()},
                                    {"shot", {{"x", 487.0}, {"angle", angle}, {"power", 1.0}}}});
    ASSERT_EQ(run.exit_code, 0) << run.err.dump();
    EXPECT_EQ(run.out["outcome"]["pocketed"], Json::array({2}));
    EXPECT_EQ(run.out["outcome"]["extra_stroke"], true);
    EXPECT_FALSE(run.out["outcome"].contains("physics"));
    EXPECT_EQ(run.out["state"]["turn_number"], 1);
    EXPECT_EQ(run.out["state"]["bodies"][2]["pocketed"], true);
}

TEST(RulesMode, PhysicsOnRequest) {
    const RulesRun run = run_rules(
        {{"shot", {{"x", 300.0}, {"angle", -1.5}, {"power", 10.0}}}, {"include_physics", true}});
    ASSERT_EQ(run.exit_code, 0);
    EXPECT_TRUE(run.out["outcome"]["physics"]["events"].is_array());
}

TEST(RulesMode, ClockExpiryAndForfeit) {
    const RulesRun clock = run_rules({{"action", "clock_expired"}});
    ASSERT_EQ(clock.exit_code, 0);
    EXPECT_EQ(clock.out["outcome"]["fouls"][0]["code"], "shot_clock_expired");
    EXPECT_EQ(clock.out["state"]["turn_seat"], 1);
    const RulesRun forfeit = run_rules({{"action", "forfeit"}, {"seat", 1}});
    ASSERT_EQ(forfeit.exit_code, 0);
    EXPECT_EQ(forfeit.out["state"]["result"]["winner_team"], 0);
}

TEST(RulesMode, RefusedMovesAndBadInputExitTwo) {
    RulesRun run = run_rules({{"shot", {{"x", 50.0}, {"angle", 0.0}, {"power", 1.0}}}});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err["error"]["code"], "x_out_of_range");
    EXPECT_EQ(run.err["error"]["path"], "shot.x");
    run = run_rules({{"seat", 1}, {"shot", {{"x", 300.0}, {"angle", 0.0}, {"power", 1.0}}}});
    EXPECT_EQ(run.err["error"]["code"], "not_your_turn");
    run = run_rules({{"state", {{"rule_set", "pool"}}}});
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(run.err["error"]["path"], "state.rule_set");
    run = run_rules({{"action", "shot"}});
    EXPECT_EQ(run.err["error"]["code"], "missing_field");
    run = run_rules({{"action", "jump"}});
    EXPECT_EQ(run.err["error"]["path"], "action");
    run = run_rules({{"extra", 1}});
    EXPECT_EQ(run.err["error"]["code"], "unknown_field");
    run = run_rules({{"action", "next_board"}});
    EXPECT_EQ(run.err["error"]["code"], "wrong_phase");
    run = run_rules(Json::array());
    EXPECT_EQ(run.exit_code, 2);
}

} // namespace
