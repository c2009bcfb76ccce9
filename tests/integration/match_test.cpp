// Whole matches between bots over real WebSocket connections to the real server.
#include "harness.hpp"

#include <gtest/gtest.h>

#include <set>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;

// A short game of each rule set: one board (icf, seed, discpool end with it), or a low freestyle
// target. No shot clock: bots always answer.
proto::CreateRoom short_game(proto::RuleSet rule_set) {
    proto::CreateRoom create;
    create.rule_set = rule_set;
    create.options.boards = 1;
    create.options.target_points = rule_set == proto::RuleSet::Freestyle ? 30 : 1;
    create.options.shot_clock_s = 0.0;
    return create;
}

// What both players must agree on once a match ended normally. Snapshots may have been dropped
// (a gap in seq): at 25 times real speed a shot sends 250 snapshots a second and more, so a
// busy machine (ctest -j2 on 2 cores, ASan) that stalls a bot's reader or the server's writes
// for some 30 ms puts a queue 8 snapshots behind and the server drops the next (WriteQueue).
// Every gap must be repaired by a keyframe.
void expect_complete(const MatchRun& run, const std::set<std::string>& reasons) {
    for (const auto* bot : {&run.creator, &run.joiner}) {
        EXPECT_TRUE(bot->failure.empty()) << bot->failure;
        EXPECT_TRUE(bot->finished);
        EXPECT_EQ(bot->games, 1);
        EXPECT_EQ(bot->decode_errors, 0);
        EXPECT_EQ(bot->unrepaired_gaps, 0);
        EXPECT_TRUE(bot->errors.empty()) << bot->errors.begin()->first;
        EXPECT_TRUE(reasons.count(bot->last_reason)) << bot->last_reason;
        EXPECT_GT(bot->snapshots, 0);
    }
    EXPECT_EQ(run.creator.seat, 0);
    EXPECT_EQ(run.joiner.seat, 1);
    EXPECT_EQ(run.creator.room_code, run.joiner.room_code);
    EXPECT_EQ(run.creator.scores, run.joiner.scores);
    EXPECT_EQ(run.creator.wins, run.joiner.losses);
    EXPECT_EQ(run.creator.losses, run.joiner.wins);
    EXPECT_EQ(run.creator.draws, run.joiner.draws);
    EXPECT_GT(run.creator.shots + run.joiner.shots, 0);
}

class FullMatch : public ::testing::TestWithParam<proto::RuleSet> {};

TEST_P(FullMatch, TwoBotsPlayToTheEnd) {
    TestServer server;
    MatchSpec spec;
    spec.create = short_game(GetParam());
    spec.seed = 11 + static_cast<std::uint64_t>(GetParam());
    spec.timeout = 60s;
    const MatchRun run = play_match(server.url(), spec);
    // The rules engine's codes of a game's end (game_end's rule), as the journal names them.
    expect_complete(run, {"target_points", "boards_played", "board_cleared", "colour_cleared",
                          "coins_exhausted", "opponent_last_coin"});
    const auto& metrics = server.server().metrics();
    EXPECT_EQ(metrics.matches_finished_total.load(), 1);
    EXPECT_EQ(metrics.shots_total.load(), run.creator.shots + run.joiner.shots);
}

INSTANTIATE_TEST_SUITE_P(EveryRuleSet, FullMatch,
                         ::testing::Values(proto::RuleSet::Icf, proto::RuleSet::Seed,
                                           proto::RuleSet::Freestyle, proto::RuleSet::DiscPool),
                         [](const auto& param_info) {
                             return std::string(proto::to_string(param_info.param));
                         });

TEST(Matches, RematchPlaysASecondGame) {
    TestServer server;
    MatchSpec spec;
    spec.create = short_game(proto::RuleSet::Freestyle);
    spec.create.options.target_points = 10;
    spec.games = 2;
    spec.timeout = 60s;
    const MatchRun run = play_match(server.url(), spec);
    EXPECT_TRUE(run.creator.failure.empty()) << run.creator.failure;
    EXPECT_TRUE(run.joiner.failure.empty()) << run.joiner.failure;
    EXPECT_EQ(run.creator.games, 2);
    EXPECT_EQ(run.joiner.games, 2);
    EXPECT_EQ(run.creator.wins + run.creator.losses + run.creator.draws, 2);
    EXPECT_EQ(server.server().metrics().matches_finished_total.load(), 2);
}

TEST(Matches, FiftyMatchesAtOnceFinishCorrectly) {
    TestServer server;
    std::vector<MatchSpec> specs(50);
    for (std::size_t i = 0; i < specs.size(); ++i) {
        specs[i].create = short_game(proto::RuleSet::Freestyle);
        specs[i].create.options.target_points = 10; // the first coin wins
        specs[i].seed = 100 + i;
        specs[i].strategy = "sampling";
        specs[i].timeout = 90s;
    }
    const auto runs = play_matches(server.url(), specs);
    std::set<std::string> codes;
    for (const auto& run : runs) {
        expect_complete(run, {"target_points", "coins_exhausted"});
        codes.insert(run.code);
    }
    EXPECT_EQ(codes.size(), runs.size()); // fifty different rooms
    const auto& metrics = server.server().metrics();
    EXPECT_EQ(metrics.matches_finished_total.load(), 50);
    // Snapshots may be dropped for a bot thread that fell behind on a busy machine (the server
    // then sends a keyframe); nobody may be disconnected for it.
    EXPECT_EQ(metrics.slow_client_disconnects_total.load(), 0);
}

} // namespace
} // namespace carrom::integration
