// Cluster mode of the PostgreSQL store (docs/cluster.md) against a real PostgreSQL server:
// ownership checked in the transaction of every write, claims of orphaned matches exactly once,
// the claim of an instance's own matches at its start.
#include "store_support.hpp"

#include "store/cluster.hpp"
#include "store/postgres_match_store.hpp"

#include <atomic>
#include <mutex>
#include <vector>

namespace carrom::store {
namespace {

using namespace std::chrono_literals;

std::string pg_query(const std::string& database, const std::string& sql) {
    const auto ran = test::postgres_server().sql(database, sql);
    EXPECT_EQ(ran.exit, 0) << ran.out;
    return ran.out;
}

// Lost matches a store reported, as "id room".
struct LostLog {
    std::mutex mutex;
    std::vector<std::string> lines;
    ClusterHandlers handlers() {
        return ClusterHandlers{{},
                               [this](const MatchId& match, const std::string& room) {
                                   const std::lock_guard lock(mutex);
                                   lines.push_back(match + " " + room);
                               },
                               {},
                               {}};
    }
    std::vector<std::string> seen() {
        const std::lock_guard lock(mutex);
        return lines;
    }
};

class PostgresClusterStore : public ::testing::Test {
protected:
    std::unique_ptr<PostgresMatchStore> open(const std::string& id,
                                             std::chrono::milliseconds lease = 60s) {
        postgres::ClusterOptions options;
        options.instance_id = id;
        options.public_url = "ws://" + id + ":7777";
        options.lease = lease;
        auto opened = PostgresMatchStore::open_cluster(url, options, test::fast_options());
        EXPECT_EQ(opened.store != nullptr, true) << opened.error->message;
        return std::move(opened.store);
    }
    void expire(const std::string& id) {
        pg_query(database, "UPDATE instances SET lease_expires = now() - interval '1 s' WHERE "
                           "id = '" +
                               id + "'");
    }
    std::string owner(const std::string& match) {
        return pg_query(database, "SELECT owner_instance, owner_epoch FROM matches WHERE id = '" +
                                      match + "'");
    }

    std::string database = test::postgres_server().create_database();
    std::string url = test::postgres_server().url(database);
};

const proto::JournalEntry kEntry{1, proto::SeatLeftEntry{0}};

TEST_F(PostgresClusterStore, AMatchIsCreatedOwnedByItsInstanceAtEpochZero) {
    auto a = open("a");
    a->create(test::created("m1"));
    a->append("m1", 0, kEntry);
    ASSERT_TRUE(a->flush(test::kFlush));
    EXPECT_EQ(owner("m1"), "a|0\n");
    EXPECT_EQ(a->cluster()->status().matches_owned, 1U);
    EXPECT_EQ(pg_query(database, "SELECT id, public_url, lease_expires > now() FROM instances"),
              "a|ws://a:7777|t\n");
}

TEST_F(PostgresClusterStore, AWriteToAMatchAnotherInstanceClaimedIsRefusedAndTheMatchReportedLost) {
    auto a = open("a");
    LostLog lost;
    a->cluster()->start(lost.handlers());
    a->create(test::created("m1"));
    a->append("m1", 0, kEntry);
    ASSERT_TRUE(a->flush(test::kFlush));
    // Instance b, live, claims the match (as PostgresCluster::claim would).
    pg_query(database, "INSERT INTO instances (id, public_url, lease_expires) VALUES ('b', "
                       "'ws://b:7777', now() + interval '1 hour')");
    pg_query(database, "UPDATE matches SET owner_instance = 'b', owner_epoch = owner_epoch + 1");
    std::vector<int> told;
    std::mutex told_mutex;
    for (int seq = 1; seq <= 2; ++seq) {
        a->append("m1", seq, kEntry, [&](bool written) {
            const std::lock_guard lock(told_mutex);
            told.push_back(written ? 1 : 0);
            // The match is reported lost before the failed write's answer.
            EXPECT_EQ(lost.seen().size(), 1U);
        });
    }
    a->set_seat_token("m1", 0, hash_token("t"));
    a->mark_finished("m1", 5);
    ASSERT_TRUE(a->flush(test::kFlush));
    EXPECT_EQ(told, (std::vector<int>{0, 0}));
    EXPECT_EQ(lost.seen(), (std::vector<std::string>{"m1 " + test::created("m1").room_code}));
    EXPECT_EQ(pg_query(database, "SELECT count(*) FROM entries"), "1\n");
    EXPECT_EQ(pg_query(database, "SELECT count(*) FROM seat_tokens"), "0\n");
    EXPECT_EQ(pg_query(database, "SELECT finished_ms IS NULL FROM matches"), "t\n");
    const ClusterStatus status = a->cluster()->status();
    EXPECT_EQ(status.matches_owned, 0U);
    EXPECT_EQ(status.matches_lost_total, 1U);
    const StoreHealth health = a->health();
    EXPECT_EQ(health.dropped_total, 4U);
    EXPECT_EQ(health.errors_total, 0U);
    EXPECT_FALSE(health.degraded);
}

TEST_F(PostgresClusterStore, AnExpiredOwnersMatchesAreClaimedOnceWithTheirJournals) {
    auto a = open("a");
    a->create(test::created("m1"));
    a->append("m1", 0, kEntry);
    a->create(test::created("m2"));
    a->mark_finished("m2", 3); // finished: never claimed
    ASSERT_TRUE(a->flush(test::kFlush));
    auto b = open("b");
    auto c = open("c");
    EXPECT_TRUE(b->load_unfinished().value.empty()); // a's lease is live
    expire("a");
    const auto claimed = b->load_unfinished();
    ASSERT_TRUE(claimed.ok()) << claimed.error->message;
    ASSERT_EQ(claimed.value.size(), 1U);
    EXPECT_EQ(claimed.value[0].id, "m1");
    ASSERT_TRUE(claimed.value[0].journal);
    EXPECT_EQ(claimed.value[0].journal->entries.size(), 1U);
    EXPECT_EQ(owner("m1"), "b|1\n");
    EXPECT_TRUE(c->load_unfinished().value.empty()); // b's lease is live
    const ClusterStatus status = b->cluster()->status();
    EXPECT_EQ(status.takeovers_total, 1U);
    EXPECT_EQ(status.matches_owned, 1U);
    // The new owner writes on; the old one cannot.
    b->append("m1", 1, kEntry);
    a->append("m1", 1, proto::JournalEntry{2, proto::SeatLeftEntry{1}});
    ASSERT_TRUE(b->flush(test::kFlush));
    ASSERT_TRUE(a->flush(test::kFlush));
    EXPECT_EQ(pg_query(database, "SELECT seq, time_ms FROM entries ORDER BY seq"), "0|1\n1|1\n");
}

TEST_F(PostgresClusterStore, AnInstanceOfTheSameIdClaimsItsOwnMatchesAtItsStart) {
    {
        auto a = open("a");
        a->create(test::created("m1"));
        ASSERT_TRUE(a->flush(test::kFlush));
    }
    // The lease ended with the store; a process of the same id claims what its id owned.
    EXPECT_EQ(pg_query(database, "SELECT lease_expires <= now() FROM instances"), "t\n");
    auto again = open("a");
    const auto claimed = again->load_unfinished();
    ASSERT_EQ(claimed.value.size(), 1U);
    EXPECT_EQ(owner("m1"), "a|1\n");
    EXPECT_EQ(again->cluster()->status().takeovers_total, 0U); // its own: no takeover
}

TEST_F(PostgresClusterStore, ASecondLiveStoreOfTheSameIdIsRefused) {
    auto a = open("a");
    postgres::ClusterOptions options;
    options.instance_id = "a";
    options.public_url = "ws://a:7777";
    auto twin = PostgresMatchStore::open_cluster(url, options, test::fast_options());
    ASSERT_EQ(twin.store, nullptr);
    EXPECT_EQ(twin.error->code, "cluster_instance_in_use");
    EXPECT_EQ(twin.error->message, "instance id a is running already on " + url +
                                       " (another live carrom-server has it)");
}

} // namespace
} // namespace carrom::store
