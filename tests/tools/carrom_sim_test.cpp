// Runs the built carrom-sim binary (CARROM_SIM_PATH) on small scenes and checks its JSON output,
// its errors and its exit codes.

#include "tools/sim_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <set>
#include <string>

namespace {

using Json = nlohmann::json;

using carrom::sim_testing::run_sim;
using carrom::sim_testing::SimRun;
using carrom::sim_testing::temp_path;

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = temp_path(name);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

SimRun run_scene(const std::string& scene, const std::string& flags = "") {
    return run_sim(flags + " " + write_temp("scene.json", scene));
}

Json parse(const std::string& text) {
    return Json::parse(text, nullptr, /*allow_exceptions=*/false);
}

const std::string kBreak =
    R"({"layout": "standard",
        "shot": {"baseline": "bottom", "x": 300, "angle": -1.5707963267948966, "power": 25}})";

// Expects exit code 2, nothing on stdout, and {"error": {code, path, message}} on stderr.
Json expect_bad_input(const SimRun& run) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    const Json err = parse(run.err);
    EXPECT_TRUE(err.contains("error")) << run.err;
    if (!err.contains("error")) {
        return Json::object();
    }
    const Json& e = err["error"];
    EXPECT_TRUE(e["code"].is_string());
    EXPECT_TRUE(e["path"].is_string());
    EXPECT_FALSE(e["message"].get<std::string>().empty());
    return e;
}

TEST(CarromSim, StandardBreakGivesEventsAndTwentyBodies) {
    const SimRun run = run_scene(kBreak);
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    ASSERT_TRUE(out.is_object()) << run.out;
    EXPECT_EQ(out["integrator"], "exact");
    ASSERT_EQ(out["bodies"].size(), 20u);
    EXPECT_EQ(out["bodies"][19]["id"], 19);
    EXPECT_EQ(out["bodies"][19]["kind"], "striker");
    ASSERT_GT(out["events"].size(), 10u);
    double previous = 0.0;
    for (const Json& event : out["events"]) {
        EXPECT_GE(event["t_s"].get<double>(), previous);
        previous = event["t_s"].get<double>();
    }
    EXPECT_EQ(out["events"][0]["kind"], "collision");
    EXPECT_GT(out["end_time_s"].get<double>(), 1.0);
    EXPECT_EQ(out["truncated"], false);
    EXPECT_TRUE(out["pocketed"].is_array());
    EXPECT_GE(out["wall_time_us"].get<double>(), 0.0);
    EXPECT_GT(out["stats"]["events"].get<int>(), 10);
    for (const Json& body : out["bodies"]) {
        if (!body["pocketed"].get<bool>()) {
            EXPECT_EQ(body["vel"], Json::array({0.0, 0.0}));
        }
    }
}

TEST(CarromSim, ExactOutputIsDeterministic) {
    const SimRun a = run_scene(kBreak);
    const SimRun b = run_scene(kBreak);
    ASSERT_EQ(a.exit_code, 0);
    Json ja = parse(a.out);
    Json jb = parse(b.out);
    EXPECT_EQ(ja["bodies"], jb["bodies"]);
    EXPECT_EQ(ja["events"], jb["events"]);
}

TEST(CarromSim, AtReportsTheStateAtThatTime) {
    // Before the striker's first contact it slides freely: y(t) = 520 - 1500 (1 - e^(-k t)) / k.
    const SimRun run = run_scene(kBreak, "--at 0.05");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["at_s"], 0.05);
    EXPECT_EQ(out["end_time_s"], 0.05);
    const Json& striker = out["bodies"][19];
    const double k = 60.0 * std::log(1.0 / 0.985);
    const double y = 520.0 - 1500.0 * (1.0 - std::exp(-k * 0.05)) / k;
    EXPECT_NEAR(striker["pos"][1].get<double>(), y, 1e-9);
    EXPECT_NEAR(striker["vel"][1].get<double>(), -1500.0 * std::exp(-k * 0.05), 1e-9);
    EXPECT_TRUE(out["events"].empty());
}

TEST(CarromSim, InvariantsHoldOnTheBreak) {
    const SimRun run = run_scene(kBreak, "--invariants --no-events");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json inv = parse(run.out)["invariants"];
    EXPECT_GT(inv["checked_times"].get<int>(), 10);
    EXPECT_LT(inv["max_overlap_px"].get<double>(), 1e-6);
    EXPECT_LT(inv["max_cushion_violation_px"].get<double>(), 1e-6);
    EXPECT_EQ(inv["energy_increased"], false);
}

TEST(CarromSim, InvariantsSeeAnOverlapFreeHeadOnHit) {
    // Checked at t = 0, at every event instant, and halfway between consecutive instants.
    const SimRun run = run_scene(R"({"bodies": [
        {"id": 0, "kind": "black", "pos": [100, 300], "vel": [800, 0]},
        {"id": 1, "kind": "white", "pos": [220, 300]}]})",
                                 "--invariants");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["events"][0]["kind"], "collision");
    std::set<double> instants{0.0};
    for (const Json& event : out["events"]) {
        instants.insert(event["t_s"].get<double>());
    }
    EXPECT_EQ(out["invariants"]["checked_times"], 2 * instants.size() - 1);
    EXPECT_LE(out["invariants"]["max_overlap_px"].get<double>(), 1e-9);
}

TEST(CarromSim, FixedIntegratorRuns) {
    const SimRun run = run_scene(kBreak, "--integrator fixed");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["integrator"], "fixed");
    EXPECT_EQ(out["dt_s"], 1.0 / 60.0);
    EXPECT_GT(out["stats"]["steps"].get<int>(), 60);
    EXPECT_EQ(out["bodies"].size(), 20u);
    EXPECT_FALSE(out["events"].empty());
}

TEST(CarromSim, FixedIntegratorTakesDtSubstepsAndAt) {
    const SimRun run = run_scene(kBreak, "--integrator fixed --dt 0.001 --substeps 4 --at 0.05");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["dt_s"], 0.00025);
    EXPECT_EQ(out["substeps"], 4);
    EXPECT_EQ(out["stats"]["steps"], 200);
    EXPECT_EQ(out["end_time_s"], 0.05);
    // Within dt-sized error of the closed form.
    const double k = 60.0 * std::log(1.0 / 0.985);
    const double y = 520.0 - 1500.0 * (1.0 - std::exp(-k * 0.05)) / k;
    EXPECT_NEAR(out["bodies"][19]["pos"][1].get<double>(), y, 0.5);
}

TEST(CarromSim, RepeatReportsMedianAndMinimum) {
    const SimRun run = run_scene(kBreak, "--repeat 5 --no-events");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["runs"], 5);
    EXPECT_LE(out["wall_time_min_us"].get<double>(), out["wall_time_us"].get<double>());
    EXPECT_FALSE(out.contains("events"));
}

TEST(CarromSim, ReadsStdin) {
    const std::string path = write_temp("stdin.json", kBreak);
    const SimRun dash = run_sim("- < " + path);
    const SimRun none = run_sim("--pretty < " + path);
    ASSERT_EQ(dash.exit_code, 0) << dash.err;
    ASSERT_EQ(none.exit_code, 0) << none.err;
    EXPECT_EQ(parse(dash.out)["bodies"], parse(none.out)["bodies"]);
    EXPECT_NE(none.out.find("\n  "), std::string::npos); // --pretty indents
}

TEST(CarromSim, BadJsonExitsWithTwo) {
    const Json e = expect_bad_input(run_scene("{\"layout\": "));
    EXPECT_EQ(e["code"], "malformed_json");
    EXPECT_EQ(e["path"], "");
}

TEST(CarromSim, OverlappingBodiesNameTheBodyAndField) {
    const Json e = expect_bad_input(run_scene(R"({"bodies": [
        {"id": 0, "kind": "black", "pos": [300, 300]},
        {"id": 5, "kind": "white", "pos": [310, 305]}]})"));
    EXPECT_EQ(e["code"], "overlap");
    EXPECT_EQ(e["path"], "bodies[1].pos");
    EXPECT_NE(e["message"].get<std::string>().find("body 5"), std::string::npos);
}

TEST(CarromSim, BadFieldNamesItsPath) {
    const Json e = expect_bad_input(run_scene(R"({"bodies": [
        {"id": 0, "kind": "black", "pos": [300, 300], "vel": [0, "fast"]}]})"));
    EXPECT_EQ(e["code"], "wrong_type");
    EXPECT_EQ(e["path"], "bodies[0].vel.y");
}

TEST(CarromSim, BodyOutsideTheCushionsIsRejected) {
    const Json e = expect_bad_input(
        run_scene(R"({"bodies": [{"id": 3, "kind": "queen", "pos": [20, 300]}]})"));
    EXPECT_EQ(e["code"], "outside_cushions");
    EXPECT_EQ(e["path"], "bodies[0].pos.x");
}

TEST(CarromSim, InvalidUtf8ExitsWithTwo) {
    const Json e = expect_bad_input(run_scene("{\"a\xff\": 1}"));
    EXPECT_EQ(e["code"], "malformed_json");
}

TEST(CarromSim, TextAfterANulByteExitsWithTwo) {
    const std::string scene = kBreak + std::string(1, '\0') + " garbage";
    const Json e = expect_bad_input(run_scene(scene));
    EXPECT_EQ(e["code"], "malformed_json");
    const std::string path = write_temp("stdin.json", scene);
    const Json from_stdin = expect_bad_input(run_sim("- < " + path));
    EXPECT_EQ(from_stdin["code"], "malformed_json");
}

TEST(CarromSim, MissingFileExitsWithTwo) {
    const Json e = expect_bad_input(run_sim(temp_path("does-not-exist.json")));
    EXPECT_EQ(e["code"], "io_error");
}

TEST(CarromSim, BadFlagsExitWithTwo) {
    const std::string scene = write_temp("flags.json", kBreak);
    for (const char* flags : {"--integrator rk4", "--dt 0", "--dt -1", "--substeps 0", "--repeat 0",
                              "--at -1", "--at nan", "--frobnicate"}) {
        const Json e = expect_bad_input(run_sim(std::string(flags) + " " + scene));
        EXPECT_EQ(e["code"], "bad_argument") << flags;
    }
}

// 64 coins on a grid, moving in all directions, with no damping, elastic contacts and pockets
// too small to reach: nothing ever stops.
std::string endless_scene(int max_events) {
    Json bodies = Json::array();
    for (int i = 0; i < 64; ++i) {
        const double angle = 0.7 * i;
        bodies.push_back({{"id", i},
                          {"kind", "black"},
                          {"pos", {80 + 62 * (i / 8), 80 + 62 * (i % 8)}},
                          {"vel", {900 * std::cos(angle), 900 * std::sin(angle)}}});
    }
    return Json{{"config",
                 {{"damping_per_s", 0},
                  {"cushion_restitution", 1},
                  {"disc_restitution", 1},
                  {"pocket_radius_px", 0.001},
                  {"max_events", max_events}}},
                {"bodies", bodies}}
        .dump();
}

TEST(CarromSim, MaxEventsAboveTheBoundIsOutOfRange) {
    const std::string scene =
        R"({"config":{"damping_per_s":1e-300,"cushion_restitution":1,"disc_restitution":1,)"
        R"("max_events":100000000},"layout":"standard","shot":{"x":300,"angle":-1.2,"power":25}})";
    const Json e = expect_bad_input(run_scene(scene));
    EXPECT_EQ(e["code"], "out_of_range");
    EXPECT_EQ(e["path"], "config.max_events");
}

TEST(CarromSim, EndlessExactSceneStopsAtTheWorkBound) {
    const SimRun run = run_scene(endless_scene(500000), "--no-events");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["truncated"], true);
    EXPECT_GE(out["stats"]["pair_tests"].get<int>(), 1 << 23);
    EXPECT_LT(out["stats"]["events"].get<int>(), 500000);
}

TEST(CarromSim, EndlessFixedStepSceneStopsAtTheWorkBound) {
    const SimRun run = run_scene(endless_scene(1000), "--integrator fixed --dt 1e-6 --no-events");
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    EXPECT_EQ(out["truncated"], true);
    EXPECT_EQ(out["stats"]["steps"], (1L << 26) / (64 * 63 / 2));
    EXPECT_LT(out["end_time_s"].get<double>(), 1.0);
}

TEST(CarromSim, HelpExitsWithZero) {
    const SimRun run = run_sim("--help");
    EXPECT_EQ(run.exit_code, 0);
    EXPECT_NE(run.out.find("--integrator"), std::string::npos);
}

} // namespace
