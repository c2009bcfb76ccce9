// Cluster mode (docs/cluster.md): carrom-server instances as real processes on one PostgreSQL of
// the test's own (tests/support/postgres_instance.hpp). The start's checks (--public-url, the
// instance id), the lease in `instances` and in /healthz and /metrics, and takeovers: a match
// played by bots on instance a, a killed with SIGKILL (or frozen with SIGSTOP past its lease),
// instance b claims the match, the bots resume their seats on b and finish, and the journal
// replays clean with consecutive turns.
#include "bot_pair.hpp"
#include "harness.hpp"

#include "support/postgres_instance.hpp"
#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <signal.h>

#include <algorithm>

#include <thread>
#include <vector>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// An instance of the cluster on data, with a 2 s lease (renewed and scanned every 0.67 s).
std::unique_ptr<test_support::ServerProcess> start_instance(const std::string& data,
                                                            const std::string& id) {
    test_support::ServerProcess::Options options = bot_server_options(data);
    options.args.insert(options.args.end(), {"--instance-id", id, "--lease", "2", "--public-url",
                                             "ws://" + id + ".cluster.test:7777"});
    return std::make_unique<test_support::ServerProcess>(options);
}

// carrom-server with these arguments after --host and --port 0: exit status and output.
CommandRun run_server(const std::string& args) {
    return run_command(std::string("timeout -s KILL 20 ") + CARROM_SERVER_PATH +
                       " --host 127.0.0.1 --port 0 --no-web " + args + " 2>&1 </dev/null");
}

std::string metric_line(const test_support::ServerProcess& server, const std::string& name) {
    const std::string text = server.get("/metrics").body;
    const auto at = text.find("\n" + name + " ");
    return at == std::string::npos ? std::string()
                                   : text.substr(at + 1, text.find('\n', at + 1) - at - 1);
}

class ClusterProcess : public ::testing::Test {
protected:
    test_support::PostgresInstance postgres;
    std::string database = postgres.create_database();
    std::string url = postgres.url(database);
};

TEST_F(ClusterProcess, APostgresqlStoreWithoutAPublicUrlIsRefusedInOneLine) {
    const CommandRun ran = run_server("--data '" + url + "'");
    EXPECT_EQ(ran.exit, 2) << ran.out;
    EXPECT_EQ(ran.out, "carrom-server: public_url_required: a PostgreSQL store runs in cluster "
                       "mode: give --public-url ws://HOST:PORT (the address clients reach this "
                       "instance at)\n");
}

TEST_F(ClusterProcess, ABadPublicUrlOrInstanceIdIsRefusedInOneLine) {
    for (const std::string bad : {"http://a:1", "ws://", "ws://a b", "ws:///x"}) {
        const CommandRun ran = run_server("--data '" + url + "' --public-url '" + bad + "'");
        EXPECT_EQ(ran.exit, 2) << bad << ": " << ran.out;
        EXPECT_EQ(ran.out.rfind("carrom-server: bad_public_url: --public-url \"" + bad + "\"", 0),
                  0U)
            << ran.out;
        EXPECT_EQ(std::count(ran.out.begin(), ran.out.end(), '\n'), 1) << ran.out;
    }
    const CommandRun ran =
        run_server("--data '" + url + "' --public-url ws://a:1 --instance-id 'a/b'");
    EXPECT_EQ(ran.exit, 2) << ran.out;
    EXPECT_EQ(ran.out, "carrom-server: bad_instance_id: --instance-id \"a/b\" is not 1 to 64 "
                       "characters of A-Z, a-z, 0-9, '.', '_' and '-'\n");
}

TEST_F(ClusterProcess, AnInstanceRegistersRenewsItsLeaseByTheDatabaseClockAndShowsIt) {
    auto a = start_instance(url, "a");
    ASSERT_NE(a->port(), 0) << a->log();
    const auto lease = [&] {
        return postgres
            .sql(database, "SELECT public_url, lease_expires > now(), lease_expires < now() + "
                           "interval '2.1 s', (extract(epoch FROM lease_expires) * 1000)::bigint "
                           "FROM instances WHERE id = 'a'")
            .out;
    };
    const std::string first = lease();
    EXPECT_EQ(first.rfind("ws://a.cluster.test:7777|t|t|", 0), 0U) << first;
    std::this_thread::sleep_for(1500ms); // two renewals
    const std::string second = lease();
    EXPECT_EQ(second.rfind("ws://a.cluster.test:7777|t|t|", 0), 0U) << second;
    EXPECT_GT(std::stoll(second.substr(second.rfind('|') + 1)),
              std::stoll(first.substr(first.rfind('|') + 1)));

    const auto health = a->get("/healthz");
    EXPECT_EQ(health.status, 200);
    EXPECT_NE(health.body.find("cluster: {\"instance\":\"a\",\"lease_expires_ms\":"),
              std::string::npos)
        << health.body;
    EXPECT_NE(health.body.find("\"lease_ok\":true,\"matches_lost_total\":0,\"matches_owned\":0,"
                               "\"public_url\":\"ws://a.cluster.test:7777\","
                               "\"takeovers_total\":0}"),
              std::string::npos)
        << health.body;
    EXPECT_EQ(metric_line(*a, "carrom_cluster_lease_ok"), "carrom_cluster_lease_ok 1");
    EXPECT_EQ(metric_line(*a, "carrom_cluster_takeovers_total"),
              "carrom_cluster_takeovers_total 0");
    EXPECT_NE(
        a->get("/metrics")
            .body.find(
                "carrom_cluster_info{instance=\"a\",public_url=\"ws://a.cluster.test:7777\"} 1"),
        std::string::npos);

    // A second live process with the same id is refused; another id joins.
    const CommandRun twin =
        run_server("--data '" + url + "' --public-url ws://twin:1 --instance-id a --lease 2");
    EXPECT_EQ(twin.exit, 2) << twin.out;
    EXPECT_NE(twin.out.find("carrom-server: cluster_instance_in_use: instance id a is running "
                            "already on "),
              std::string::npos)
        << twin.out;
    auto b = start_instance(url, "b");
    ASSERT_NE(b->port(), 0) << b->log();
    EXPECT_EQ(postgres.sql(database, "SELECT id FROM instances ORDER BY id").out, "a\nb\n");

    // SIGTERM ends the lease at once.
    b->terminate();
    EXPECT_EQ(
        postgres.sql(database, "SELECT lease_expires <= now() FROM instances WHERE id = 'b'").out,
        "t\n");
}

TEST_F(ClusterProcess, AnSqliteServerHasNoClusterLinesAndNeedsNoPublicUrl) {
    test_support::TempDir dir("carrom_cluster");
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = dir.file("c.db");
    test_support::ServerProcess server(options);
    ASSERT_NE(server.port(), 0) << server.log();
    EXPECT_EQ(server.get("/healthz").body, "ok\n");
    EXPECT_EQ(server.get("/metrics").body.find("carrom_cluster"), std::string::npos);
}

// The number in a metric line "NAME N" of the server (-1 if none).
long metric_value(const test_support::ServerProcess& server, const std::string& name) {
    const std::string line = metric_line(server, name);
    return line.empty() ? -1 : std::stol(line.substr(name.size() + 1));
}

// Each bot of a rated Pair has one rated game in the store, counted once (docs/ratings.md).
void expect_rated_once(const test_support::ServerProcess& server) {
    for (const char* name : {"creator", "joiner"}) {
        const auto answer = server.get(std::string("/players/") + name);
        ASSERT_EQ(answer.status, 200) << answer.body;
        const auto player = nlohmann::json::parse(answer.body, nullptr, false);
        ASSERT_TRUE(player.is_object()) << answer.body;
        ASSERT_EQ(player["ratings"].size(), 1U) << answer.body;
        EXPECT_EQ(player["ratings"][0]["games"], 1) << answer.body;
        EXPECT_NE(player["ratings"][0]["rating"], 1500.0) << answer.body;
    }
}

// A match on a, a killed (SIGKILL) or frozen (SIGSTOP, then SIGCONT once b took over) while a
// shot moves; the bots resume on b by themselves and finish. rated: the match is rated, and its
// result moves each bot's rating once.
void take_over(const std::string& url, bool freeze, bool rated = false) {
    auto a = start_instance(url, "a");
    auto b = start_instance(url, "b");
    ASSERT_NE(a->port(), 0) << a->log();
    ASSERT_NE(b->port(), 0) << b->log();
    Pair pair(a->url(), 11, rated);
    ASSERT_FALSE(pair.creator->summary().room_code.empty());
    pair.run([&] { return pair.shots >= 1; }, 10s);
    EXPECT_EQ(metric_value(*a, "carrom_cluster_matches_owned"), 1);
    bool stopped = false;
    Clock::time_point stopped_at;
    pair.hook = [&](const proto::ServerMessage& m) {
        if (!stopped && pair.shots >= 3 && std::holds_alternative<proto::Snapshot>(m)) {
            if (freeze) {
                ::kill(a->process().pid(), SIGSTOP);
            } else {
                a->kill9();
            }
            stopped = true;
            stopped_at = Clock::now();
            pair.move_to(b->url()); // the players' next connection reaches b
        }
    };
    pair.run([&] { return stopped; }, 20s);
    ASSERT_TRUE(stopped) << pair.shots << " shots; " << pair.creator->summary().failure;
    pair.hook = nullptr;
    const auto taken = b->wait_log("taken over from instance a", Clock::now() + 6s);
    ASSERT_TRUE(taken) << b->log();
    const double seconds = std::chrono::duration<double>(Clock::now() - stopped_at).count();
    EXPECT_LT(seconds, 2.0 + 0.67 + 2.0); // lease + scan interval + margin
    std::fprintf(stderr, "taken over %.2f s after the %s\n", seconds, freeze ? "SIGSTOP" : "kill");
    if (freeze) {
        ::kill(a->process().pid(), SIGCONT);
        // The woken owner finds the match gone and closes its room's connections (4004).
        EXPECT_TRUE(a->wait_log("is run by another instance now", Clock::now() + 5s)) << a->log();
    }
    pair.run([] { return false; }, 30s);
    pair.expect_finished();
    EXPECT_EQ(metric_value(*b, "carrom_cluster_takeovers_total"), 1);
    EXPECT_EQ(metric_value(*b, "carrom_cluster_matches_owned"), 0);
    EXPECT_GT(expect_finished_journals_clean(*b, 1), 3);
    if (rated) {
        expect_rated_once(*b);
    }
    if (freeze) {
        EXPECT_EQ(metric_value(*a, "carrom_cluster_matches_lost_total"), 1);
        EXPECT_EQ(metric_value(*a, "carrom_cluster_matches_owned"), 0);
        EXPECT_EQ(metric_value(*a, "carrom_store_errors_total"), 0);
    }
    if (::testing::Test::HasFailure()) {
        std::fprintf(stderr, "a:\n%s\nb:\n%s", a->log().c_str(), b->log().c_str());
    }
}

TEST_F(ClusterProcess, AKilledOwnersMatchIsTakenOverAndTheBotsFinishOnTheOtherInstance) {
    take_over(url, false);
}

TEST_F(ClusterProcess, ARatedMatchTakenOverFromAKilledOwnerIsRatedOnce) {
    take_over(url, false, true);
}

TEST_F(ClusterProcess, AFrozenOwnerWakesToAMatchTakenOverWritesNothingAndClosesItsSockets) {
    take_over(url, true);
}

// PostgreSQL stopped longer than the lease while a match plays on a, then started again: the
// match pauses at its next stroke (`paused`, nothing of the stroke streamed), new matches are
// refused (store_unavailable), /healthz says why; every lease lapsed meanwhile, and the
// instances renew theirs before any claims, so the match stays on a (no takeover, no connection
// closed), gets `resumed` and finishes with every stroke written once (docs/cluster.md, "The
// database down").
TEST_F(ClusterProcess, ADatabaseOutageLongerThanTheLeaseMovesNoMatch) {
    // b first: its rounds come just before a's, so b is back before a renews.
    auto b = start_instance(url, "b");
    auto a = start_instance(url, "a");
    ASSERT_NE(a->port(), 0) << a->log();
    ASSERT_NE(b->port(), 0) << b->log();
    PauseWatch watch;
    Pair pair(a->url(), 13);
    pair.hook = [&](const proto::ServerMessage& m) { watch.see(m); };
    pair.run([&] { return pair.shots >= 3; }, 20s);
    ASSERT_GE(pair.shots, 3);
    ASSERT_TRUE(postgres.stop());
    pair.run([] { return false; }, 3s); // the next stroke waits for its write, retried
    EXPECT_EQ(watch.paused, 1);
    EXPECT_EQ(watch.resumed, 0);
    EXPECT_EQ(watch.reason, "store");
    const std::string health = a->get("/healthz").body;
    EXPECT_TRUE(
        health.starts_with("degraded: cluster lease not renewed; match store not writing ("))
        << health;
    std::fprintf(stderr, "/healthz of a during the outage: %s", health.c_str());
    expect_new_matches_refused(a->url());
    ASSERT_TRUE(postgres.start());
    const auto started_at = Clock::now();
    EXPECT_TRUE(a->wait_log("cluster: lease renewed again", Clock::now() + 10s)) << a->log();
    EXPECT_TRUE(b->wait_log("cluster: lease renewed again", Clock::now() + 10s)) << b->log();
    pair.run([] { return false; }, 30s);
    pair.expect_finished(0);
    ASSERT_TRUE(a->get("/healthz").body.find("\"lease_ok\":true") != std::string::npos);
    EXPECT_EQ(metric_value(*b, "carrom_cluster_takeovers_total"), 0);
    EXPECT_EQ(metric_value(*a, "carrom_cluster_matches_lost_total"), 0);
    // The writes held in memory reach the database once a retry finds it back (backoff up to
    // 5 s); the read connection broke with the restart and reconnects at a later read.
    const auto deadline = Clock::now() + 15s;
    while (Clock::now() < deadline && (metric_value(*a, "carrom_store_pending") != 0 ||
                                       a->get("/matches?player=creator&limit=1").status != 200)) {
        std::this_thread::sleep_for(100ms);
    }
    EXPECT_EQ(metric_value(*a, "carrom_store_pending"), 0);
    EXPECT_TRUE(a->get("/healthz").body.starts_with("ok\ncluster: ")) << a->get("/healthz").body;
    EXPECT_EQ(watch.paused, 1);
    EXPECT_EQ(watch.resumed, 1);
    EXPECT_EQ(watch.streamed_while_paused, 0);
    std::fprintf(stderr, "paused %.2f s; resumed %.2f s after PostgreSQL started\n",
                 std::chrono::duration<double>(watch.resumed_at - watch.paused_at).count(),
                 std::chrono::duration<double>(watch.resumed_at - started_at).count());
    EXPECT_GT(expect_finished_journals_clean(*a, 1), 3);
    if (::testing::Test::HasFailure()) {
        std::fprintf(stderr, "a:\n%s\nb:\n%s", a->log().c_str(), b->log().c_str());
    }
}

// Twenty matches on a, a killed while they play: b claims all twenty in one round, restores
// them, and every pair resumes on b and finishes.
TEST_F(ClusterProcess, TwentyMatchesOfAKilledOwnerAreAllTakenOverAndFinish) {
    auto a = start_instance(url, "a");
    auto b = start_instance(url, "b");
    ASSERT_NE(a->port(), 0) << a->log();
    ASSERT_NE(b->port(), 0) << b->log();
    constexpr int kMatches = 20;
    std::vector<std::unique_ptr<Pair>> pairs;
    for (int i = 0; i < kMatches; ++i) {
        pairs.push_back(std::make_unique<Pair>(a->url(), static_cast<std::uint64_t>(200 + i)));
        ASSERT_FALSE(pairs.back()->creator->summary().room_code.empty());
    }
    const auto run_all = [&](bool to_the_end, std::chrono::milliseconds timeout) {
        std::vector<std::thread> runs;
        for (auto& pair : pairs) {
            runs.emplace_back([p = pair.get(), to_the_end, timeout] {
                p->run([p, to_the_end] { return !to_the_end && p->shots >= 2; }, timeout);
            });
        }
        for (auto& run : runs) {
            run.join();
        }
    };
    run_all(false, 15s);
    EXPECT_EQ(metric_value(*a, "carrom_cluster_matches_owned"), kMatches);
    a->kill9();
    const auto killed_at = Clock::now();
    for (auto& pair : pairs) {
        pair->move_to(b->url());
    }
    // Every match running on b: the twentieth "taken over: match" line of b.
    std::optional<std::string> last;
    while (Clock::now() < killed_at + 10s) {
        const std::string log = b->log_of_this_start();
        int count = 0;
        for (auto at = log.find("taken over: match"); at != std::string::npos;
             at = log.find("taken over: match", at + 1)) {
            ++count;
        }
        if (count == kMatches) {
            last = log;
            break;
        }
        std::this_thread::sleep_for(20ms);
    }
    ASSERT_TRUE(last) << b->log();
    std::fprintf(stderr, "%d matches running on b %.2f s after the kill\n", kMatches,
                 std::chrono::duration<double>(Clock::now() - killed_at).count());
    run_all(true, 40s);
    for (const auto& pair : pairs) {
        pair->expect_finished();
    }
    EXPECT_EQ(metric_value(*b, "carrom_cluster_takeovers_total"), kMatches);
    EXPECT_GT(expect_finished_journals_clean(*b, kMatches), 3 * kMatches);
}

} // namespace
} // namespace carrom::integration
