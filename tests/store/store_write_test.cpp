// Writing to and reading from the store, on each backend (an SQLite file, a PostgreSQL
// database): journals come back exactly
// (and replay), after a reopen too; unfinished matches are listed for recovery with their seat
// token hashes; a game's end finishes its match; players' match lists; items the database refuses
// are dropped and counted; concurrent appends from several threads all land, in order.

#include "store_support.hpp"

#include "carrom/proto/journal_replay.hpp"

#include <atomic>
#include <thread>
#include <vector>

namespace carrom::store {
namespace {

using StoreWrite = test::StoreTest;
CARROM_STORE_BACKENDS(StoreWrite);

proto::MatchJournal game_journal(const std::string& id, std::uint64_t seed,
                                 rules::RuleSet rule_set = rules::RuleSet::Icf) {
    proto::MatchJournal journal = proto::test::random_game(rule_set, seed).journal();
    journal.created.match_id = id;
    return journal;
}

// The first `count` entries of a journal (a game still running).
proto::MatchJournal running(proto::MatchJournal journal, std::size_t count) {
    journal.entries.resize(count);
    return journal;
}

TEST_P(StoreWrite, AJournalComesBackExactlyAndReplays) {
    auto store = open();
    const proto::MatchJournal journal = game_journal("m1", 3);
    test::store_journal(*store, journal);
    ASSERT_TRUE(store->flush(test::kFlush));
    const auto loaded = store->journal("m1");
    ASSERT_TRUE(loaded.ok()) << loaded.error->message;
    ASSERT_TRUE(loaded.value.has_value());
    EXPECT_EQ(*loaded.value, journal);
    EXPECT_TRUE(proto::replay(*loaded.value).ok());
    EXPECT_FALSE(store->journal("nope").value.has_value());
}

TEST_P(StoreWrite, JournalsSurviveAReopen) {
    const proto::MatchJournal a = game_journal("a", 1, rules::RuleSet::Freestyle);
    const proto::MatchJournal b = game_journal("b", 2, rules::RuleSet::DiscPool);
    {
        auto store = open();
        test::store_journal(*store, a);
        test::store_journal(*store, b);
        // No flush: closing writes what is queued.
    }
    auto store = open();
    EXPECT_EQ(*store->journal("a").value, a);
    EXPECT_EQ(*store->journal("b").value, b);
}

TEST_P(StoreWrite, EveryAppendIsToldOnceThatItIsWritten) {
    auto store = open();
    const proto::MatchJournal journal = game_journal("m1", 5);
    store->create(journal.created);
    std::vector<std::atomic<int>> told(journal.entries.size());
    std::atomic<int> failures{0};
    for (std::size_t i = 0; i < journal.entries.size(); ++i) {
        store->append("m1", static_cast<std::int64_t>(i), journal.entries[i],
                      [&told, &failures, i](bool written) {
                          told[i].fetch_add(1);
                          failures += written ? 0 : 1;
                      });
    }
    ASSERT_TRUE(store->flush(test::kFlush));
    for (const auto& t : told) {
        EXPECT_EQ(t.load(), 1);
    }
    EXPECT_EQ(failures.load(), 0);
    const StoreHealth health = store->health();
    EXPECT_FALSE(health.degraded);
    EXPECT_EQ(health.errors_total, 0U);
    EXPECT_EQ(health.pending, 0U);
    EXPECT_EQ(health.written_total, journal.entries.size() + 1);
}

TEST_P(StoreWrite, UnfinishedMatchesAreListedForRecoveryOldestFirst) {
    {
        auto store = open();
        proto::MatchJournal finished = game_journal("done", 1); // ends with a game_end outcome
        proto::MatchJournal older = running(game_journal("older", 2), 6);
        proto::MatchJournal newer = running(game_journal("newer", 3), 9);
        proto::MatchJournal abandoned = running(game_journal("gone", 4), 2);
        older.created.time_ms = 1000;
        newer.created.time_ms = 2000;
        test::store_journal(*store, newer);
        test::store_journal(*store, finished);
        test::store_journal(*store, older);
        test::store_journal(*store, abandoned);
        store->mark_finished("gone", 5000);
        ASSERT_TRUE(store->flush(test::kFlush));
    }
    auto store = open();
    const auto loaded = store->load_unfinished();
    ASSERT_TRUE(loaded.ok()) << loaded.error->message;
    ASSERT_EQ(loaded.value.size(), 2U);
    EXPECT_EQ(loaded.value[0].id, "older");
    EXPECT_EQ(loaded.value[1].id, "newer");
    ASSERT_TRUE(loaded.value[0].journal.has_value());
    EXPECT_EQ(loaded.value[0].journal->entries.size(), 6U);
    EXPECT_EQ(loaded.value[1].journal->entries.size(), 9U);
    EXPECT_FALSE(loaded.value[0].error.has_value());
    // A running game replays to its current state.
    EXPECT_TRUE(proto::replay(*loaded.value[1].journal).ok());
}

TEST_P(StoreWrite, SeatTokenHashesAreStoredReplacedAndCleared) {
    const TokenHash ann = hash_token("0123456789abcdef0123456789abcdef");
    const TokenHash bea = hash_token("fedcba9876543210fedcba9876543210");
    const TokenHash bea2 = hash_token("00000000000000000000000000000000");
    {
        auto store = open();
        test::store_journal(*store, running(game_journal("m", 1), 3));
        store->set_seat_token("m", 0, ann);
        store->set_seat_token("m", 1, bea);
        store->set_seat_token("m", 1, bea2);
        ASSERT_TRUE(store->flush(test::kFlush));
    }
    {
        auto store = open();
        const auto loaded = store->load_unfinished();
        ASSERT_EQ(loaded.value.size(), 1U);
        ASSERT_EQ(loaded.value[0].seat_tokens.size(), 2U);
        EXPECT_EQ(loaded.value[0].seat_tokens[0], ann);
        EXPECT_EQ(loaded.value[0].seat_tokens[1], bea2);
        store->set_seat_token("m", 0, std::nullopt);
    }
    auto store = open();
    const auto loaded = store->load_unfinished();
    EXPECT_FALSE(loaded.value[0].seat_tokens[0].has_value());
    EXPECT_EQ(loaded.value[0].seat_tokens[1], bea2);
}

// The database holds hashes only: no token appears anywhere in it (the SQLite file's bytes; a
// pg_dump of the PostgreSQL database, where bytea is hex).
TEST_P(StoreWrite, TheDatabaseNeverHoldsATokenInClear) {
    const std::string token = "c0ffee00c0ffee00c0ffee00c0ffee00";
    {
        auto store = open();
        test::store_journal(*store, running(game_journal("m", 1), 3));
        store->set_seat_token("m", 0, hash_token(token));
    }
    const TokenHash hash = hash_token(token);
    const std::string bytes = snapshot();
    std::string stored_hash(reinterpret_cast<const char*>(hash.data()), hash.size());
    if (postgres()) {
        stored_hash = to_hex(hash);
        std::string token_hex;
        for (const char c : token) {
            static constexpr char kDigits[] = "0123456789abcdef";
            const auto byte = static_cast<unsigned char>(c);
            token_hex += kDigits[byte >> 4];
            token_hex += kDigits[byte & 15];
        }
        EXPECT_EQ(bytes.find(token_hex), std::string::npos);
    }
    EXPECT_EQ(bytes.find(token), std::string::npos);
    EXPECT_NE(bytes.find(stored_hash), std::string::npos);
}

TEST_P(StoreWrite, PlayersMatchListsAreNewestFirstWithResults) {
    auto store = open();
    for (int i = 0; i < 5; ++i) {
        proto::MatchJournal journal =
            game_journal("m" + std::to_string(i), static_cast<std::uint64_t>(i + 1));
        journal.created.seats = {proto::JournalSeat{"ann", false},
                                 proto::JournalSeat{i % 2 == 0 ? "bea" : "cat", false}};
        journal.created.time_ms = 1000 * (i + 1);
        if (i == 4) {
            journal = running(journal, 3);
            journal.entries.push_back(proto::JournalEntry{9000, proto::SeatLeftEntry{1}});
            journal.entries.push_back(
                proto::JournalEntry{9001, proto::SeatJoinedEntry{1, "dan", false}});
        }
        test::store_journal(*store, journal);
    }
    ASSERT_TRUE(store->flush(test::kFlush));

    const auto ann = store->recent_matches("ann", 3);
    ASSERT_TRUE(ann.ok()) << ann.error->message;
    ASSERT_EQ(ann.value.size(), 3U);
    EXPECT_EQ(ann.value[0].id, "m4");
    EXPECT_EQ(ann.value[1].id, "m3");
    EXPECT_EQ(ann.value[2].id, "m2");
    EXPECT_FALSE(ann.value[0].finished_ms.has_value()); // still running
    EXPECT_FALSE(ann.value[0].result.has_value());
    EXPECT_EQ(ann.value[1].players, (std::vector<std::string>{"ann", "cat"}));
    EXPECT_EQ(ann.value[1].room_code, "ABCDEF");
    EXPECT_EQ(ann.value[1].rule_set, rules::RuleSet::Icf);
    EXPECT_EQ(ann.value[1].created_ms, 4000);
    ASSERT_TRUE(ann.value[1].result.has_value());
    ASSERT_TRUE(ann.value[1].finished_ms.has_value());
    EXPECT_EQ(ann.value[1].scores.size(), 2U);

    const auto bea = store->recent_matches("bea", 100);
    ASSERT_EQ(bea.value.size(), 3U); // m4 (as seated at the start), m2, m0
    EXPECT_EQ(bea.value[2].id, "m0");
    const auto dan = store->recent_matches("dan", 10); // joined m4 later
    ASSERT_EQ(dan.value.size(), 1U);
    EXPECT_EQ(dan.value[0].id, "m4");
    EXPECT_TRUE(store->recent_matches("nobody", 10).value.empty());
    EXPECT_EQ(store->recent_matches("ann", 0).value.size(), 1U); // limit 1..100
}

// The result in the list is the game's, as its last outcome recorded it.
TEST_P(StoreWrite, AFinishedMatchListsItsResultAndScores) {
    auto store = open();
    const proto::MatchJournal journal = game_journal("m", 8, rules::RuleSet::Freestyle);
    test::store_journal(*store, journal);
    ASSERT_TRUE(store->flush(test::kFlush));
    const proto::OutcomeRecord* last = nullptr;
    for (const auto& entry : journal.entries) {
        last = proto::outcome_of(entry.event) ? proto::outcome_of(entry.event) : last;
    }
    ASSERT_TRUE(last != nullptr && last->game_end.has_value());
    const auto list = store->recent_matches("ann", 10);
    ASSERT_EQ(list.value.size(), 1U);
    EXPECT_EQ(list.value[0].result, last->game_end);
    EXPECT_EQ(list.value[0].scores, last->scores);
    EXPECT_EQ(list.value[0].finished_ms, journal.entries.back().time_ms);
}

TEST_P(StoreWrite, AnAppendToAnUnknownMatchIsDroppedAndCounted) {
    auto store = open();
    std::atomic<int> told_false{0};
    store->append("ghost", 0, proto::JournalEntry{1, proto::SeatLeftEntry{0}},
                  [&](bool written) { told_false += written ? 0 : 1; });
    test::store_journal(*store, running(game_journal("m", 1), 2)); // later items still land
    EXPECT_TRUE(store->flush(test::kFlush));
    EXPECT_EQ(told_false.load(), 1);
    const StoreHealth health = store->health();
    EXPECT_EQ(health.dropped_total, 1U);
    EXPECT_EQ(health.errors_total, 1U);
    EXPECT_FALSE(health.degraded);
    EXPECT_EQ(store->journal("m").value->entries.size(), 2U);
    EXPECT_FALSE(store->journal("ghost").value.has_value());
}

TEST_P(StoreWrite, AnEntryNumberWrittenTwiceIsDroppedAndTheFirstKept) {
    auto store = open();
    test::store_journal(*store, running(game_journal("m", 1), 2));
    store->append("m", 1, proto::JournalEntry{1, proto::SeatLeftEntry{0}});
    EXPECT_TRUE(store->flush(test::kFlush));
    EXPECT_EQ(store->health().dropped_total, 1U);
    EXPECT_EQ(store->journal("m").value->entries, running(game_journal("m", 1), 2).entries);
}

// A journal missing an entry (as a dropped append leaves it) is reported for that match only.
TEST_P(StoreWrite, AJournalWithAGapIsABadJournalForThatMatchOnly) {
    auto store = open();
    const proto::MatchJournal whole = running(game_journal("whole", 1), 4);
    test::store_journal(*store, whole);
    const proto::MatchJournal gap = running(game_journal("gap", 2), 4);
    store->create(gap.created);
    for (std::size_t i : {0U, 1U, 3U}) {
        store->append("gap", static_cast<std::int64_t>(i), gap.entries[i]);
    }
    ASSERT_TRUE(store->flush(test::kFlush));
    const auto loaded = store->load_unfinished();
    ASSERT_TRUE(loaded.ok());
    ASSERT_EQ(loaded.value.size(), 2U);
    for (const RecoveredMatch& m : loaded.value) {
        if (m.id == "gap") {
            ASSERT_TRUE(m.error.has_value());
            EXPECT_EQ(m.error->code, "store_bad_journal");
            EXPECT_EQ(m.error->message,
                      "the stored journal of match gap is damaged: entry 2 is missing");
            EXPECT_FALSE(m.journal.has_value());
        } else {
            EXPECT_EQ(*m.journal, whole);
        }
    }
    EXPECT_EQ(store->journal("gap").error->code, "store_bad_journal");
}

TEST_P(StoreWrite, ConcurrentAppendsFromSeveralThreadsAllLandInOrder) {
    constexpr int kThreads = 8;
    std::vector<proto::MatchJournal> journals;
    for (int t = 0; t < kThreads; ++t) {
        journals.push_back(
            game_journal("t" + std::to_string(t), static_cast<std::uint64_t>(t + 1),
                         t % 2 == 0 ? rules::RuleSet::Icf : rules::RuleSet::Freestyle));
    }
    std::atomic<int> written{0};
    {
        auto store = open();
        std::vector<std::thread> threads;
        for (int t = 0; t < kThreads; ++t) {
            threads.emplace_back([&, t] {
                const proto::MatchJournal& j = journals[static_cast<std::size_t>(t)];
                store->create(j.created);
                for (std::size_t i = 0; i < j.entries.size(); ++i) {
                    store->append(j.created.match_id, static_cast<std::int64_t>(i), j.entries[i],
                                  [&written](bool ok) { written += ok ? 1 : 0; });
                }
            });
        }
        for (auto& thread : threads) {
            thread.join();
        }
        ASSERT_TRUE(store->flush(test::kFlush));
        EXPECT_EQ(store->health().errors_total, 0U);
    }
    std::size_t total = 0;
    auto store = open();
    for (const proto::MatchJournal& j : journals) {
        EXPECT_EQ(*store->journal(j.created.match_id).value, j);
        total += j.entries.size();
    }
    EXPECT_EQ(written.load(), static_cast<int>(total));
}

} // namespace
} // namespace carrom::store
