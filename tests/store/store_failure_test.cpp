// The store, on each backend, when writing fails: entries stay in memory, in order, and are
// retried; the store says it is degraded and counts each failed attempt; callers are told once,
// when their entry is written (or dropped); when the fault clears everything is written exactly
// once. Failures are injected
// through the store's test seam (fail_writes), which rolls each transaction back before its COMMIT
// as a real write error would; on PostgreSQL also by stopping the database server mid-run. And a
// crash of the process (SIGKILL) loses no entry the store said was written.

#include "store_support.hpp"

#include "store/postgres_match_store.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace carrom::store {
namespace {

using StoreFailure = test::StoreTest;
CARROM_STORE_BACKENDS(StoreFailure);

using namespace std::chrono_literals;

// Polls cond every millisecond for at most 10 s.
template <class F> bool eventually(F cond) {
    for (int i = 0; i < 10000; ++i) {
        if (cond()) {
            return true;
        }
        std::this_thread::sleep_for(1ms);
    }
    return cond();
}

struct Faulty {
    std::shared_ptr<std::atomic<bool>> failing = std::make_shared<std::atomic<bool>>(true);
    StoreOptions options() const {
        StoreOptions o = test::fast_options();
        o.fail_writes = [f = failing] { return f->load(); };
        return o;
    }
};

proto::MatchJournal journal_of(const std::string& id, std::uint64_t seed) {
    proto::MatchJournal journal = proto::test::random_game(rules::RuleSet::Icf, seed).journal();
    journal.created.match_id = id;
    return journal;
}

TEST_P(StoreFailure, FailedWritesWaitInMemoryAndLandOnceTheFaultClears) {
    Faulty fault;
    auto store = open(fault.options());
    const proto::MatchJournal journal = journal_of("m", 1);
    store->create(journal.created);
    std::vector<std::atomic<int>> told(journal.entries.size());
    std::atomic<int> told_written{0};
    for (std::size_t i = 0; i < journal.entries.size(); ++i) {
        store->append("m", static_cast<std::int64_t>(i), journal.entries[i], [&, i](bool written) {
            told[i].fetch_add(1);
            told_written += written ? 1 : 0;
        });
    }
    ASSERT_TRUE(eventually([&] { return store->health().errors_total >= 3; }));
    StoreHealth health = store->health();
    EXPECT_TRUE(health.degraded);
    EXPECT_EQ(health.pending, journal.entries.size() + 1);
    EXPECT_EQ(health.last_error, "injected write failure (test seam)");
    EXPECT_EQ(health.written_total, 0U);
    EXPECT_FALSE(store->flush(50ms));
    EXPECT_FALSE(store->journal("m").value.has_value()); // nothing half-written
    for (const auto& t : told) {
        EXPECT_EQ(t.load(), 0); // a failed attempt tells nothing: the caller waits
    }

    fault.failing->store(false);
    ASSERT_TRUE(store->flush(test::kFlush));
    health = store->health();
    EXPECT_FALSE(health.degraded);
    EXPECT_EQ(health.pending, 0U);
    EXPECT_EQ(health.written_total, journal.entries.size() + 1);
    EXPECT_EQ(health.dropped_total, 0U);
    EXPECT_EQ(*store->journal("m").value, journal); // every entry once, in order
    for (const auto& t : told) {
        EXPECT_EQ(t.load(), 1);
    }
    EXPECT_EQ(told_written.load(), static_cast<int>(journal.entries.size())); // told written
}

TEST_P(StoreFailure, EntriesQueuedDuringAnOutageFollowTheFailedOnes) {
    Faulty fault;
    auto store = open(fault.options());
    const proto::MatchJournal journal = journal_of("m", 2);
    const std::size_t half = journal.entries.size() / 2;
    store->create(journal.created);
    for (std::size_t i = 0; i < half; ++i) {
        store->append("m", static_cast<std::int64_t>(i), journal.entries[i]);
    }
    ASSERT_TRUE(eventually([&] { return store->health().degraded; }));
    for (std::size_t i = half; i < journal.entries.size(); ++i) {
        store->append("m", static_cast<std::int64_t>(i), journal.entries[i]);
    }
    const std::uint64_t errors = store->health().errors_total;
    ASSERT_TRUE(eventually([&] { return store->health().errors_total > errors; }));
    fault.failing->store(false);
    ASSERT_TRUE(store->flush(test::kFlush));
    EXPECT_EQ(*store->journal("m").value, journal);
}

TEST_P(StoreFailure, ItemsBeyondTheMemoryBoundAreDroppedAndCounted) {
    Faulty fault;
    StoreOptions options = fault.options();
    options.max_pending = 5;
    auto store = open(options);
    const proto::MatchJournal journal = journal_of("m", 3);
    store->create(journal.created);
    std::atomic<int> refused{0};
    std::atomic<int> written_told{0};
    for (std::size_t i = 0; i < 10; ++i) {
        store->append("m", static_cast<std::int64_t>(i), journal.entries[i], [&](bool written) {
            refused += written ? 0 : 1;
            written_told += written ? 1 : 0;
        });
    }
    const StoreHealth health = store->health();
    EXPECT_EQ(health.dropped_total, 6U);
    EXPECT_GE(health.errors_total, 6U);
    EXPECT_EQ(health.pending, 5U);
    // 6 dropped (and told) at once; the 4 kept are told once they are written.
    EXPECT_EQ(refused.load(), 6);
    EXPECT_TRUE(eventually([&] { return store->health().errors_total >= 8; }));
    EXPECT_EQ(written_told.load(), 0);
    fault.failing->store(false);
    EXPECT_TRUE(eventually([&] { return store->health().pending == 0; }));
    EXPECT_EQ(refused.load(), 6);
    EXPECT_TRUE(eventually([&] { return written_told.load() == 4; }));
    EXPECT_EQ(store->journal("m").value->entries.size(), 4U);
}

TEST_P(StoreFailure, ClosingWhileWritesFailGivesUpAfterTheCloseTimeout) {
    Faulty fault;
    StoreOptions options = fault.options();
    options.close_timeout = 100ms;
    {
        auto store = open(options);
        store->create(journal_of("m", 4).created);
        ASSERT_TRUE(eventually([&] { return store->health().degraded; }));
        const auto start = std::chrono::steady_clock::now();
        store.reset();
        EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
    }
    auto store = open();
    EXPECT_FALSE(store->journal("m").value.has_value());
}

// A child process appends entries in bursts and reports each one the store says is written; the
// parent kills it with SIGKILL in the middle, then finds every reported entry in the file.
TEST_P(StoreFailure, AKilledProcessLosesNoEntryItWasToldWasWritten) {
    const proto::MatchJournal journal = journal_of("m", 5);
    const std::string where = location(); // before the fork: the child writes there
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(fds[0]);
        auto opened = open_match_store(where, test::fast_options());
        if (opened.error) {
            ::_exit(3);
        }
        opened.store->create(journal.created);
        for (std::int64_t seq = 0;; ++seq) { // until killed
            const auto& entry =
                journal.entries[static_cast<std::size_t>(seq) % journal.entries.size()];
            opened.store->append("m", seq, entry, [fd = fds[1], seq](bool written) {
                if (written) {
                    const auto unused = ::write(fd, &seq, sizeof seq);
                    (void)unused;
                }
            });
            if (seq % 64 == 63) { // bursts: the queue always holds entries not yet written
                std::this_thread::sleep_for(1ms);
            }
        }
    }
    ::close(fds[1]);
    std::int64_t told = -1;
    std::int64_t seq = 0;
    while (told < 500 && ::read(fds[0], &seq, sizeof seq) == sizeof seq) {
        told = std::max(told, seq);
    }
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    while (::read(fds[0], &seq, sizeof seq) == sizeof seq) { // told before it died
        told = std::max(told, seq);
    }
    ::close(fds[0]);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child ended by itself: " << status;
    ASSERT_GE(told, 500);

    auto store = open(); // validates the file (quick_check) first
    ASSERT_NE(store, nullptr);
    const auto loaded = store->journal("m");
    ASSERT_TRUE(loaded.ok()) << loaded.error->message;
    ASSERT_TRUE(loaded.value.has_value());
    EXPECT_GT(static_cast<std::int64_t>(loaded.value->entries.size()), told);
}

// The PostgreSQL server stopped in the middle of a match and started again: the appends made
// meanwhile wait in memory (the store degraded, reads failing with store_cannot_connect), then
// land once each, in order, after the ones written before; each caller is told once.
TEST(PostgresStoreFailure, AServerStoppedMidMatchLosesAndDoublesNothing) {
    auto& server = test::postgres_server();
    auto opened =
        PostgresMatchStore::open(server.url(server.create_database()), test::fast_options());
    ASSERT_NE(opened.store, nullptr) << opened.error->message;
    PostgresMatchStore& store = *opened.store;
    const proto::MatchJournal journal = journal_of("m", 6);
    const std::size_t half = journal.entries.size() / 2;
    std::vector<std::atomic<int>> told(journal.entries.size());
    const auto append = [&](std::size_t i) {
        store.append("m", static_cast<std::int64_t>(i), journal.entries[i],
                     [&told, i](bool) { told[i].fetch_add(1); });
    };
    store.create(journal.created);
    for (std::size_t i = 0; i < half; ++i) {
        append(i);
    }
    ASSERT_TRUE(store.flush(test::kFlush));

    ASSERT_TRUE(server.stop());
    for (std::size_t i = half; i < journal.entries.size(); ++i) {
        append(i);
    }
    ASSERT_TRUE(eventually([&] { return store.health().errors_total >= 3; }));
    EXPECT_TRUE(store.health().degraded);
    EXPECT_EQ(store.health().pending, journal.entries.size() - half);
    EXPECT_FALSE(store.flush(50ms));
    const auto unreadable = store.journal("m");
    ASSERT_TRUE(unreadable.error.has_value());
    EXPECT_EQ(unreadable.error->code, "store_cannot_connect") << unreadable.error->message;

    ASSERT_TRUE(server.start());
    ASSERT_TRUE(store.flush(test::kFlush));
    const StoreHealth health = store.health();
    EXPECT_FALSE(health.degraded);
    EXPECT_EQ(health.dropped_total, 0U);
    EXPECT_EQ(health.written_total, journal.entries.size() + 1);
    const auto loaded = store.journal("m"); // the reader connects again too
    ASSERT_TRUE(loaded.ok()) << loaded.error->message;
    EXPECT_EQ(*loaded.value, journal);
    for (const auto& t : told) {
        EXPECT_EQ(t.load(), 1);
    }
}

} // namespace
} // namespace carrom::store
