// `carrom-sim --replay FILE`: the built binary verifies journals of seeded games (exit 0), finds a
// changed stroke (exit 1) and refuses unreadable, invalid and other-version journals with a code
// and a sentence (exit 2).

#include "proto/journal_support.hpp"

#include "carrom/proto/journal_json.hpp"
#include "tools/sim_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <string>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;

using sim_testing::run_sim;
using sim_testing::SimRun;
using sim_testing::temp_path;

std::string write_temp(const std::string& text) {
    const std::string path = temp_path("journal.json");
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

SimRun replay_journal(const MatchJournal& journal) {
    return run_sim("--replay " + write_temp(journal_to_json(journal).dump()));
}

Json parse(const std::string& text) {
    return Json::parse(text, nullptr, /*allow_exceptions=*/false);
}

// Exit code 2, nothing on stdout, {"error": {code, path, message}} on stderr; returns the error.
Json expect_refused(const SimRun& run) {
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    const Json err = parse(run.err);
    if (!err.contains("error")) {
        ADD_FAILURE() << run.err;
        return Json::object();
    }
    EXPECT_FALSE(err["error"]["message"].get<std::string>().empty());
    return err["error"];
}

TEST(CarromSimReplay, ACleanJournalPrintsEveryStrokeAndExitsZero) {
    const auto game = test::random_game(rules::RuleSet::Icf, 11);
    const SimRun run = replay_journal(game.journal());
    ASSERT_EQ(run.exit_code, 0) << run.err;
    const Json out = parse(run.out);
    ASSERT_TRUE(out.is_object()) << run.out;
    EXPECT_EQ(out["match"], "m-0001");
    EXPECT_EQ(out["rule_set"], "icf");
    EXPECT_EQ(out["mismatches"], 0);
    EXPECT_EQ(out["complete"], true);
    EXPECT_EQ(out["scores"], Json(game.state().scores));
    ASSERT_TRUE(out["result"].is_object());
    std::size_t strokes = 0;
    for (const Json& step : out["steps"]) {
        EXPECT_EQ(step["matches"], true);
        const auto& entry = game.journal().entries[step["entry"].get<std::size_t>()];
        EXPECT_EQ(step["type"], std::string(event_type(entry.event)));
        if (const auto* stroke = std::get_if<StrokeEntry>(&entry.event)) {
            ++strokes;
            EXPECT_EQ(step["result_hash"], hash_to_hex(stroke->result_hash));
            EXPECT_EQ(step["turn"], stroke->turn);
            EXPECT_EQ(step["outcome"], outcome_record_to_json(stroke->outcome));
        }
    }
    EXPECT_GT(strokes, 10U);
}

TEST(CarromSimReplay, AChangedStrokeExitsOneAndNamesTheDifference) {
    MatchJournal journal = test::random_game(rules::RuleSet::Freestyle, 3).journal();
    std::size_t index = 0;
    while (!std::holds_alternative<StrokeEntry>(journal.entries[index].event)) {
        ++index;
    }
    auto& stroke = std::get<StrokeEntry>(journal.entries[index].event);
    stroke.shot.angle_rad = std::nextafter(stroke.shot.angle_rad, 10.0);
    const SimRun run = replay_journal(journal);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    const Json out = parse(run.out);
    ASSERT_TRUE(out.is_object()) << run.out;
    EXPECT_GE(out["mismatches"].get<int>(), 1);
    const Json* changed = nullptr;
    for (const Json& step : out["steps"]) {
        if (step["entry"] == index) {
            changed = &step;
        }
    }
    ASSERT_NE(changed, nullptr);
    EXPECT_EQ((*changed)["matches"], false);
    bool names_hash = false;
    for (const Json& d : (*changed)["differences"]) {
        names_hash = names_hash || d.get<std::string>().rfind("result_hash: journal ", 0) == 0;
    }
    EXPECT_TRUE(names_hash) << changed->dump();
}

TEST(CarromSimReplay, AnInputTheRulesRefuseExitsOne) {
    test::JournalRecorder game(test::make_created(rules::RuleSet::Icf));
    MatchJournal journal = game.journal();
    journal.entries.push_back(
        JournalEntry{5, StrokeEntry{0, 1, Shot{300.0, 1.5, 10.0}, 0,
                                    OutcomeRecord{0, {}, {}, {0, 0}, 0, {}, {}}}});
    const SimRun run = replay_journal(journal);
    EXPECT_EQ(run.exit_code, 1) << run.err;
    const Json out = parse(run.out);
    ASSERT_TRUE(out.is_object()) << run.out;
    EXPECT_EQ(out["complete"], false);
    EXPECT_EQ(out["steps"][0]["refused"]["code"], "not_your_turn");
}

TEST(CarromSimReplay, MalformedJsonExitsTwo) {
    const Json e = expect_refused(run_sim("--replay " + write_temp("{\"format\": 1, \"match\"")));
    EXPECT_EQ(e["code"], "malformed_json");
}

TEST(CarromSimReplay, AnInvalidJournalExitsTwoNamingTheField) {
    Json j = journal_to_json(test::random_game(rules::RuleSet::Icf, 1, 5).journal());
    j["entries"][0]["seat"] = 7;
    const Json e = expect_refused(run_sim("--replay " + write_temp(j.dump())));
    EXPECT_EQ(e["code"], "out_of_range");
    EXPECT_EQ(e["path"], "entries[0].seat");
}

TEST(CarromSimReplay, AMissingFileExitsTwo) {
    const Json e = expect_refused(run_sim("--replay " + temp_path("absent.json")));
    EXPECT_EQ(e["code"], "io_error");
}

TEST(CarromSimReplay, AnotherRulesVersionExitsTwo) {
    MatchJournal journal = test::random_game(rules::RuleSet::Icf, 1, 5).journal();
    journal.created.versions.rules = rules::kRulesVersion + 1;
    const Json e = expect_refused(replay_journal(journal));
    EXPECT_EQ(e["code"], "version_mismatch");
    EXPECT_EQ(e["path"], "match.versions");
}

TEST(CarromSimReplay, ReplayAndRulesModesExcludeEachOther) {
    const Json e = expect_refused(run_sim("--replay --rules " + write_temp("{}")));
    EXPECT_EQ(e["code"], "bad_argument");
}

} // namespace
} // namespace carrom::proto
