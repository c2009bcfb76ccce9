// The carrom-load executable end to end: it starts its own carrom-server on 127.0.0.1, drives a
// few bot matches for a short window and prints the figures of docs/server-load.md as JSON.
// Bounded: 4 matches, a 3 s window, the server at 4x speed so that shots end inside it; the run
// ends by itself in about 6 s. The --replace test: 3 matches for 8 s at 8x speed, about 10 s.
#include "harness.hpp"
#include "support/read_file.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace carrom::integration {
namespace {

std::string load_command(const std::string& args) {
    return std::string(CARROM_LOAD_PATH) + " --server-bin " + CARROM_SERVER_PATH + " " + args +
           " 2>/dev/null";
}

TEST(LoadCli, DrivesMatchesAndReportsTheirFigures) {
    const CommandRun ran = run_command(load_command("--matches 4 --ramp 0 --warmup 1 --duration 3 "
                                                    "--think-ms 300 --think-spread-ms 200 --seed 7 "
                                                    "--server-arg=--time-scale=4"));
    ASSERT_EQ(ran.exit, 0) << ran.out;
    const auto out = nlohmann::json::parse(ran.out);
    EXPECT_EQ(out["matches"], 4);
    EXPECT_EQ(out["think_ms"], 300);
    EXPECT_EQ(out["think_spread_ms"], 200);
    EXPECT_EQ(out["held_at_start"], 4);
    EXPECT_EQ(out["held_at_end"], 4);
    EXPECT_EQ(out["client_failures"], 0);
    EXPECT_EQ(out["errors_received"], 0);
    EXPECT_EQ(out["messages_malformed"], 0); // every message of the real server read
    EXPECT_EQ(out["server_exit"], 0);        // stopped by SIGTERM, exits cleanly
    EXPECT_GT(out["lag_samples"].get<long>(), 0);
    EXPECT_GT(out["bytes_per_client_per_s_moving"].get<double>(), 0.0);
    EXPECT_GT(out["server_kib_per_match"].get<double>(), 0.0);
    const double p50 = out["snapshot_lag_ms_p50"];
    const double p99 = out["snapshot_lag_ms_p99"];
    const double max = out["snapshot_lag_ms_max"];
    EXPECT_LE(p50, p99);
    EXPECT_LE(p99, max);
    // The timeline: one row per second of the window, [second, samples, p99, max], whose samples
    // are at most all samples of the window.
    const auto& timeline = out["lag_by_second"];
    ASSERT_TRUE(timeline.is_array());
    ASSERT_GE(timeline.size(), 3u);
    long in_timeline = 0;
    for (std::size_t s = 0; s < timeline.size(); ++s) {
        ASSERT_EQ(timeline[s].size(), 4u);
        EXPECT_EQ(timeline[s][0], s);
        in_timeline += timeline[s][1].get<long>();
        EXPECT_LE(timeline[s][2].get<double>(), timeline[s][3].get<double>());
        EXPECT_LE(timeline[s][3].get<double>(), max);
    }
    EXPECT_GT(in_timeline, 0);
    EXPECT_LE(in_timeline, out["lag_samples"].get<long>());
}

// --replace (what scripts/soak.sh runs): when a game ends both players leave and a new match
// takes its place, so the server sees rooms open, fill, end and close all along; the progress
// file gets a line of running totals every --progress-s seconds.
TEST(LoadCli, ReplacesFinishedMatchesAndWritesProgressLines) {
    const test_support::TempDir dir("carrom_load_replace");
    const std::string progress = dir.file("progress.jsonl");
    const CommandRun ran = run_command(
        load_command("--matches 3 --ramp 0 --warmup 0 --duration 8 --think-ms 0 --seed 7 "
                     "--target-points 1 --replace --no-samples --progress-s 2 --progress-out " +
                     progress + " --server-arg=--time-scale=8"));
    ASSERT_EQ(ran.exit, 0) << ran.out;
    const auto out = nlohmann::json::parse(ran.out);
    EXPECT_EQ(out["replace"], true);
    EXPECT_EQ(out["target_points"], 1);
    EXPECT_EQ(out["client_failures"], 0);
    EXPECT_EQ(out["errors_received"], 0) << out["errors_by_code"].dump();
    EXPECT_EQ(out["server_exit"], 0);
    EXPECT_EQ(out["lag_samples"], 0); // --no-samples
    const long finished = out["matches_finished"];
    EXPECT_GE(finished, 2); // a game to 1 point ends at the first coin pocketed
    // Every finished match started a new one in its slot.
    EXPECT_EQ(out["matches_started"].get<long>(), 3 + finished);

    std::istringstream lines(test_support::read_file(progress));
    std::string line;
    std::vector<nlohmann::json> rows;
    while (std::getline(lines, line)) {
        rows.push_back(nlohmann::json::parse(line));
    }
    ASSERT_EQ(rows.size(), 4u); // at 2, 4, 6 and 8 s
    long previous = 0;
    for (const auto& row : rows) {
        EXPECT_EQ(row["errors_received"], 0);
        EXPECT_EQ(row["client_failures"], 0);
        EXPECT_LE(row["held"].get<long>(), 3);
        EXPECT_GE(row["matches_finished"].get<long>(), previous);
        previous = row["matches_finished"];
        EXPECT_EQ(row["matches_started"].get<long>(), 3 + previous);
    }
    EXPECT_LE(previous, finished);
}

TEST(LoadCli, RejectsASpreadLargerThanThePause) {
    const CommandRun ran =
        run_command(load_command("--matches 1 --think-ms 100 --think-spread-ms 200"));
    EXPECT_EQ(ran.exit, 2);
}

} // namespace
} // namespace carrom::integration
