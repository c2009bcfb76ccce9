// A carrom-server process whose SQLite match store cannot write (CARROM_TEST_STORE_FAIL_FILE) in
// the middle of a bot match (docs/cluster.md, "The database down"): the players get `paused`
// and nothing of the waiting stroke; new rooms and quick match get store_unavailable; /healthz
// says why; once the store writes again the players get `resumed`, the match finishes, and its
// journal is complete with consecutive turns. The PostgreSQL case is in cluster_process_test.cpp.
#include "bot_pair.hpp"

#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;

TEST(StoreOutageProcess, AStoreThatCannotWritePausesTheMatchRefusesNewOnesAndLosesNothing) {
    test_support::TempDir dir("carrom_store_outage");
    const std::string fail = dir.file("fail");
    test_support::ServerProcess::Options options = bot_server_options(dir.file("c.db"));
    options.env = {"CARROM_TEST_STORE_FAIL_FILE=" + fail};
    test_support::ServerProcess server(options);
    ASSERT_NE(server.port(), 0) << server.log();
    PauseWatch watch;
    Pair pair(server.url(), 17);
    pair.hook = [&](const proto::ServerMessage& m) { watch.see(m); };
    pair.run([&] { return pair.shots >= 2; }, 20s);
    ASSERT_GE(pair.shots, 2);

    std::ofstream(fail) << "fail\n";
    pair.run([&] { return watch.paused > 0; }, 10s);
    ASSERT_EQ(watch.paused, 1) << server.log();
    EXPECT_EQ(watch.reason, "store");
    EXPECT_EQ(watch.message,
              "The server cannot save the last stroke because its database does not answer; the "
              "match goes on when it is back.");
    const int shots_paused = pair.shots;
    const std::string health = server.get("/healthz").body;
    EXPECT_TRUE(health.starts_with("degraded: match store not writing (")) << health;
    EXPECT_NE(health.find(" waiting): injected write failure (test seam)\n"), std::string::npos)
        << health;
    expect_new_matches_refused(server.url());
    pair.run([] { return false; }, 1500ms); // the match stays paused, its shot clock stopped
    EXPECT_EQ(pair.shots, shots_paused);
    EXPECT_EQ(watch.resumed, 0);

    std::filesystem::remove(fail);
    pair.run([] { return false; }, 60s);
    pair.expect_finished(0);
    EXPECT_EQ(watch.paused, 1);
    EXPECT_EQ(watch.resumed, 1);
    EXPECT_EQ(watch.streamed_while_paused, 0);
    EXPECT_TRUE(pair.creator->summary().errors.empty());
    bool healthy = false;
    for (int i = 0; i < 100 && !healthy; ++i) {
        healthy = server.get("/healthz").body == "ok\n";
        std::this_thread::sleep_for(50ms);
    }
    EXPECT_TRUE(healthy) << server.get("/healthz").body;
    EXPECT_GT(expect_finished_journals_clean(server, 1), shots_paused);
    if (::testing::Test::HasFailure()) {
        std::fprintf(stderr, "%s", server.log().c_str());
    }
}

} // namespace
} // namespace carrom::integration
