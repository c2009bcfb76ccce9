// replay(): seeded games of every rule set, journaled as the server journals them, replay to
// every recorded outcome and the same final state; any change to an input or a record is found
// and named; journals of other versions and impossible heads are refused.

#include "journal_support.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "carrom/rules/state_hash.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace carrom::proto {
namespace {

using test::JournalRecorder;
using test::random_game;

constexpr rules::RuleSet kRuleSets[] = {rules::RuleSet::Icf, rules::RuleSet::Seed,
                                        rules::RuleSet::Freestyle, rules::RuleSet::DiscPool};

std::size_t inputs_in(const MatchJournal& journal) {
    std::size_t n = 0;
    for (const JournalEntry& e : journal.entries) {
        n += outcome_of(e.event) != nullptr ? 1U : 0U;
    }
    return n;
}

std::string all_differences(const ReplayResult& r) {
    std::string out;
    for (const ReplayStep& step : r.steps) {
        for (const std::string& d : step.differences) {
            out += "entries[" + std::to_string(step.entry) + "] " + d + "\n";
        }
    }
    return out;
}

// The index of the n-th stroke entry.
std::size_t nth_stroke(const MatchJournal& journal, int n) {
    for (std::size_t i = 0; i < journal.entries.size(); ++i) {
        if (std::holds_alternative<StrokeEntry>(journal.entries[i].event) && n-- == 0) {
            return i;
        }
    }
    ADD_FAILURE() << "the journal has too few strokes";
    return 0;
}

const ReplayStep& step_for(const ReplayResult& r, std::size_t entry) {
    for (const ReplayStep& step : r.steps) {
        if (step.entry == entry) {
            return step;
        }
    }
    ADD_FAILURE() << "no step for entries[" << entry << "]";
    return r.steps.front();
}

TEST(JournalReplay, SeededGamesOfEveryRuleSetReplayToEveryRecordedOutcome) {
    for (rules::RuleSet rule_set : kRuleSets) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const JournalRecorder game = random_game(rule_set, seed);
            const ReplayResult r = replay(game.journal());
            SCOPED_TRACE(std::string(rules::to_string(rule_set)) + " seed " + std::to_string(seed));
            EXPECT_TRUE(r.ok()) << all_differences(r);
            EXPECT_EQ(r.steps.size(), inputs_in(game.journal()));
            EXPECT_GT(r.steps.size(), 10U);
            EXPECT_EQ(rules::hash_match_state(r.state), rules::hash_match_state(game.state()));
            EXPECT_EQ(r.state.phase, rules::Phase::GameOver);
        }
    }
}

// The games above end in more than one way; a test that only saw forfeits would miss a wrong
// board or game result.
TEST(JournalReplay, SeededGamesEndBoardsAndGamesByTheRules) {
    int boards = 0;
    int games_by_rules = 0;
    for (rules::RuleSet rule_set : kRuleSets) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const JournalRecorder game = random_game(rule_set, seed);
            boards += static_cast<int>(game.state().boards.size());
            const bool forfeited = game.state().result->reason == rules::RuleCode::Forfeit;
            games_by_rules += forfeited ? 0 : 1;
        }
    }
    EXPECT_GE(boards, 6);
    EXPECT_GE(games_by_rules, 4);
}

TEST(JournalReplay, AJournalReplaysTheSameAfterAJsonRoundTrip) {
    const JournalRecorder game = random_game(rules::RuleSet::Icf, 7);
    const std::string text = journal_to_json(game.journal()).dump();
    const auto decoded = decode_journal_text(text);
    ASSERT_TRUE(decoded.ok()) << decoded.error->path << ": " << decoded.error->message;
    EXPECT_EQ(decoded.value, game.journal());
    const ReplayResult r = replay(decoded.value);
    EXPECT_TRUE(r.ok()) << all_differences(r);
    EXPECT_EQ(rules::hash_match_state(r.state), rules::hash_match_state(game.state()));
}

TEST(JournalReplay, StepsCarryTheReplayedOutcomes) {
    const JournalRecorder game = random_game(rules::RuleSet::Freestyle, 2);
    const ReplayResult r = replay(game.journal());
    ASSERT_TRUE(r.ok());
    for (const ReplayStep& step : r.steps) {
        const JournalEvent& event = game.journal().entries[step.entry].event;
        EXPECT_EQ(step.replayed, *outcome_of(event));
        if (const auto* stroke = std::get_if<StrokeEntry>(&event)) {
            EXPECT_EQ(step.result_hash, stroke->result_hash);
            EXPECT_TRUE(step.outcome.shot_taken);
            EXPECT_TRUE(step.outcome.physics.events.empty()) << "physics kept unasked";
        }
    }
}

TEST(JournalReplay, PhysicsAndTrajectoriesAreKeptWhenAsked) {
    const JournalRecorder game = random_game(rules::RuleSet::Icf, 3, 20);
    ReplayOptions options;
    options.record_trajectory = true;
    const ReplayResult r = replay(game.journal(), options);
    ASSERT_TRUE(r.ok());
    const ReplayStep& first = r.steps.front();
    EXPECT_FALSE(first.outcome.physics.events.empty());
    EXPECT_FALSE(first.outcome.physics.trajectory.segments.empty());
}

// The last bit of one stroke's power changes its simulation: the replay names the stroke and
// the differing result hash, and the strokes before it still match.
TEST(JournalReplay, AStrokeChangedInItsLastBitIsFound) {
    JournalRecorder game = random_game(rules::RuleSet::Icf, 4);
    MatchJournal journal = game.journal();
    const std::size_t index = nth_stroke(journal, 5);
    auto& stroke = std::get<StrokeEntry>(journal.entries[index].event);
    stroke.shot.power = std::nextafter(stroke.shot.power, 0.0);
    const ReplayResult r = replay(journal);
    EXPECT_FALSE(r.ok());
    ASSERT_GE(r.mismatches, 1);
    const ReplayStep* first_bad = nullptr;
    for (const ReplayStep& step : r.steps) {
        if (!step.differences.empty()) {
            first_bad = &step;
            break;
        }
    }
    ASSERT_NE(first_bad, nullptr);
    EXPECT_EQ(first_bad->entry, index);
    bool names_hash = false;
    for (const std::string& d : first_bad->differences) {
        names_hash = names_hash || d.rfind("result_hash: journal ", 0) == 0;
    }
    EXPECT_TRUE(names_hash) << all_differences(r);
}

TEST(JournalReplay, ARecordedScoreChangedIsNamed) {
    MatchJournal journal = random_game(rules::RuleSet::Freestyle, 5).journal();
    const std::size_t index = nth_stroke(journal, 2);
    auto& stroke = std::get<StrokeEntry>(journal.entries[index].event);
    const std::vector<int> real = stroke.outcome.scores;
    stroke.outcome.scores[0] += 10;
    const ReplayResult r = replay(journal);
    ASSERT_EQ(r.mismatches, 1);
    EXPECT_TRUE(r.complete);
    const ReplayStep& step = step_for(r, index);
    ASSERT_EQ(step.differences.size(), 1U);
    EXPECT_EQ(step.differences[0],
              "scores: journal [" + std::to_string(real[0] + 10) + ", " + std::to_string(real[1]) +
                  "], replay [" + std::to_string(real[0]) + ", " + std::to_string(real[1]) + "]");
}

TEST(JournalReplay, AChangedStateHashIsNamed) {
    MatchJournal journal = random_game(rules::RuleSet::Seed, 1).journal();
    const std::size_t index = nth_stroke(journal, 0);
    std::get<StrokeEntry>(journal.entries[index].event).outcome.state_hash ^= 1U;
    const ReplayResult r = replay(journal);
    ASSERT_EQ(r.mismatches, 1);
    const ReplayStep& step = step_for(r, index);
    ASSERT_EQ(step.differences.size(), 1U);
    EXPECT_EQ(step.differences[0].rfind("state_hash: journal ", 0), 0U);
}

TEST(JournalReplay, AWrongTurnNumberIsNamed) {
    MatchJournal journal = random_game(rules::RuleSet::Icf, 2, 10).journal();
    const std::size_t index = nth_stroke(journal, 1);
    const int turn = std::get<StrokeEntry>(journal.entries[index].event).turn;
    std::get<StrokeEntry>(journal.entries[index].event).turn = turn + 1;
    const ReplayResult r = replay(journal);
    ASSERT_EQ(r.mismatches, 1);
    EXPECT_EQ(step_for(r, index).differences,
              (std::vector<std::string>{"turn: journal " + std::to_string(turn + 1) + ", replay " +
                                        std::to_string(turn)}));
}

// A stroke by the seat not to move: the rules refuse it and the replay stops there.
TEST(JournalReplay, AnInputTheRulesRefuseStopsTheReplay) {
    MatchJournal journal = random_game(rules::RuleSet::Icf, 6).journal();
    const std::size_t index = nth_stroke(journal, 3);
    auto& stroke = std::get<StrokeEntry>(journal.entries[index].event);
    stroke.seat = 1 - stroke.seat;
    const ReplayResult r = replay(journal);
    EXPECT_FALSE(r.complete);
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.steps.empty());
    const ReplayStep& last = r.steps.back();
    EXPECT_EQ(last.entry, index);
    ASSERT_TRUE(last.refused.has_value());
    EXPECT_EQ(last.refused->code, rules::RuleErrorCode::NotYourTurn);
}

TEST(JournalReplay, AStrokeAfterTheGameEndedIsRefused) {
    JournalRecorder game(test::make_created(rules::RuleSet::Icf));
    game.forfeit(0, ForfeitReason::Left);
    MatchJournal journal = game.journal();
    journal.entries.push_back(
        JournalEntry{0, StrokeEntry{1, 1, Shot{300.0, -1.5, 10.0}, 0, OutcomeRecord{}}});
    const ReplayResult r = replay(journal);
    ASSERT_EQ(r.steps.size(), 2U);
    EXPECT_EQ(r.steps[1].refused->code, rules::RuleErrorCode::GameOver);
}

TEST(JournalReplay, MembershipEntriesChangeNothing) {
    JournalRecorder game(test::make_created(rules::RuleSet::Icf));
    game.member(SeatDroppedEntry{1});
    game.member(SeatReturnedEntry{1});
    game.member(SeatLeftEntry{1});
    game.member(SeatJoinedEntry{1, "bea", false});
    const ReplayResult r = replay(game.journal());
    EXPECT_TRUE(r.ok());
    EXPECT_TRUE(r.steps.empty());
    EXPECT_EQ(rules::hash_match_state(r.state),
              rules::hash_match_state(initial_state(game.journal().created)));
}

// A rematch's journal: seat 1 breaks and the turn numbers go on from the previous game.
TEST(JournalReplay, ARematchJournalStartsFromItsFirstTurnAndBreaker) {
    rules::RulesConfig config = test::short_game();
    config.first_breaker = 1;
    MatchCreated created = test::make_created(rules::RuleSet::Icf, config, "m-0002");
    created.rematch_of = "m-0001";
    created.first_turn = 41;
    JournalRecorder game(created);
    EXPECT_EQ(game.state().turn_seat, 1);
    EXPECT_EQ(game.state().turn_number, 41);
    std::mt19937_64 rng(9);
    for (int i = 0; i < 12; ++i) {
        game.stroke(test::aimed_shot(game.state(), game.state().turn_seat, rng));
    }
    EXPECT_EQ(std::get<StrokeEntry>(game.journal().entries.front().event).turn, 41);
    const ReplayResult r = replay(game.journal());
    EXPECT_TRUE(r.ok()) << all_differences(r);
    EXPECT_EQ(rules::hash_match_state(r.state), rules::hash_match_state(game.state()));
}

TEST(JournalReplay, AnotherPhysicsVersionIsRefusedWithBothVersionsNamed) {
    MatchJournal journal = random_game(rules::RuleSet::Icf, 1, 5).journal();
    journal.created.versions.physics = kPhysicsVersion + 1;
    const ReplayResult r = replay(journal);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->code, "version_mismatch");
    EXPECT_EQ(r.error->message, "the journal was written with physics version " +
                                    std::to_string(kPhysicsVersion + 1) + " and rules version " +
                                    std::to_string(rules::kRulesVersion) +
                                    "; this build has physics version " +
                                    std::to_string(kPhysicsVersion) + " and rules version " +
                                    std::to_string(rules::kRulesVersion));
    EXPECT_TRUE(r.steps.empty());
    EXPECT_FALSE(r.ok());
}

TEST(JournalReplay, AnotherRulesVersionIsRefused) {
    MatchCreated created = test::make_created(rules::RuleSet::Icf);
    created.versions.rules = rules::kRulesVersion + 1;
    ASSERT_TRUE(check_versions(created).has_value());
    EXPECT_EQ(check_versions(created)->code, "version_mismatch");
    created.versions.rules = rules::kRulesVersion;
    EXPECT_FALSE(check_versions(created).has_value());
}

TEST(JournalReplay, AHeadThatCannotStartAGameIsABadJournal) {
    MatchJournal seats;
    seats.created = test::make_created(rules::RuleSet::Icf);
    seats.created.seats.pop_back();
    EXPECT_EQ(replay(seats).error->code, "bad_journal");
    EXPECT_EQ(replay(seats).error->path, "match.seats");

    MatchJournal config;
    config.created = test::make_created(rules::RuleSet::Icf);
    config.created.rules.seat_count = 3;
    EXPECT_EQ(replay(config).error->code, "bad_journal");

    MatchJournal physics;
    physics.created = test::make_created(rules::RuleSet::Icf);
    physics.created.physics.coin_radius_px = -1.0;
    EXPECT_EQ(replay(physics).error->code, "bad_journal");
}

} // namespace
} // namespace carrom::proto
