// carrom-server with a match store (--data) as a real process: bot matches journaled and served
// by GET /matches (each journal replays clean), a --data the store cannot use (exit 2, one line,
// the file untouched), and write failures injected through CARROM_TEST_STORE_FAIL_FILE while
// matches run (/healthz and /metrics say so; the matches pause, then go on; the journals end up
// complete).
#include "harness.hpp"
#include "journal_check.hpp"

#include "support/server_process.hpp"
#include "support/temp_dir.hpp"

#include <SQLiteCpp/SQLiteCpp.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <future>
#include <sstream>
#include <thread>

#include <stdlib.h>
#include <unistd.h>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;

// A temporary directory anyone may use (the read-only test runs carrom-server as nobody).
class SharedTempDir : public test_support::TempDir {
public:
    SharedTempDir() : test_support::TempDir("carrom_store_proc") {
        fs::permissions(path(), fs::perms::all, fs::perm_options::add);
    }
};

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

using test_support::ServerProcess;
using Http = ServerProcess::Http;

// carrom-server with the store at `data`, no shot clock, logging warnings.
ServerProcess::Options server_options(const std::string& data,
                                      const std::vector<std::string>& env = {}) {
    ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = data;
    options.args = {"--shot-clock",
                    "0",
                    "--time-scale",
                    "25",
                    "--log-level",
                    "warn",
                    "--max-connections-per-address",
                    "1000"};
    options.env = env;
    return options;
}

std::vector<MatchSpec> short_matches(int count) {
    std::vector<MatchSpec> specs;
    for (int i = 0; i < count; ++i) {
        MatchSpec spec;
        spec.create.rule_set = proto::RuleSet::Freestyle;
        spec.create.options.target_points = 30;
        spec.create.options.shot_clock_s = 0.0;
        spec.seed = static_cast<std::uint64_t>(100 + i);
        specs.push_back(spec);
    }
    return specs;
}

// Every match of the list: served, finished with a result, its journal replays clean.
int expect_served_journals_clean(const ServerProcess& server, std::size_t count) {
    const Http list = server.get("/matches?player=creator&limit=100");
    EXPECT_EQ(list.status, 200) << list.body;
    const auto json = nlohmann::json::parse(list.body);
    EXPECT_EQ(json["format"], 1);
    const auto& matches = json["matches"];
    EXPECT_EQ(matches.size(), count);
    int strokes = 0;
    for (const auto& m : matches) {
        const std::string id = m["id"];
        EXPECT_EQ(m["players"], nlohmann::json::array({"creator", "joiner"}));
        EXPECT_FALSE(m["result"].is_null()) << id;
        EXPECT_FALSE(m["finished_ms"].is_null()) << id;
        const Http journal = server.get("/matches/" + id);
        EXPECT_EQ(journal.status, 200) << id;
        const JournalCheck check = check_journal(journal.body);
        EXPECT_TRUE(check.problem.empty()) << id << ": " << check.problem;
        EXPECT_TRUE(check.game_over) << id;
        EXPECT_TRUE(check.turns_in_order) << id;
        EXPECT_GT(check.strokes, 0) << id;
        strokes += check.strokes;
    }
    return strokes;
}

TEST(StoreProcess, BotMatchesAreJournaledServedAndReplayClean) {
    SharedTempDir dir;
    ServerProcess server(server_options(dir.file("c.db")));
    ASSERT_NE(server.port(), 0);
    const int count = 50; // the 50-match check
    const auto runs = play_matches(server.url(), short_matches(count));
    for (const auto& run : runs) {
        ASSERT_TRUE(run.creator.finished && run.joiner.finished) << run.creator.failure;
    }
    const int strokes = expect_served_journals_clean(server, count);
    EXPECT_GT(strokes, count);
    EXPECT_EQ(server.get("/matches/nosuchmatch").status, 404);
    EXPECT_EQ(server.get("/matches/bad%20id").status, 400);
    EXPECT_EQ(server.get("/matches?player=creator&limit=101").status, 400);
    EXPECT_EQ(server.get("/matches?limit=5").status, 400);
    const Http two = server.get("/matches?player=joiner&limit=2");
    EXPECT_EQ(nlohmann::json::parse(two.body)["matches"].size(), 2U);
}

TEST(StoreProcess, WithoutAStoreTheMatchApiIsDisabled) {
    ServerProcess server(server_options("none"));
    ASSERT_NE(server.port(), 0);
    const Http answer = server.get("/matches/abc");
    EXPECT_EQ(answer.status, 503);
    EXPECT_EQ(nlohmann::json::parse(answer.body)["error"]["code"], "store_disabled");
    const Http metrics = server.get("/metrics");
    EXPECT_NE(metrics.body.find("carrom_store_errors_total 0"), std::string::npos);
}

// carrom-server --data PATH that must fail: exit 2 and one line; as nobody when root (so that
// permissions count).
struct Refusal {
    int exit = -1;
    std::string out;
};
Refusal start_refused(const std::string& path, bool unprivileged = false) {
    std::string command =
        std::string("timeout 10 ") +
        (unprivileged && ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups "
                                          : "") +
        CARROM_SERVER_PATH + " --port 0 --data '" + path + "' 2>&1";
    const CommandRun ran = run_command(command);
    return {ran.exit, ran.out};
}

void make_database(const std::string& path) {
    ServerProcess server(server_options(path));
    ASSERT_NE(server.port(), 0);
}

TEST(StoreProcess, ADataFileTheStoreCannotUseStopsTheStartAndStaysUntouched) {
    SharedTempDir dir;
    const std::string text = dir.file("notes.txt");
    std::ofstream(text) << "not a database\n";
    const std::string good = dir.file("good.db");
    make_database(good);
    const std::string good_bytes = read_bytes(good);
    ASSERT_GT(good_bytes.size(), 512U);
    const std::string truncated = dir.file("truncated.db");
    std::ofstream(truncated, std::ios::binary) << good_bytes.substr(0, good_bytes.size() / 2 + 100);
    const std::string newer = dir.file("newer.db");
    fs::copy_file(good, newer);
    {
        SQLite::Database db(newer, SQLite::OPEN_READWRITE);
        db.exec("PRAGMA user_version = 99");
    }
    const std::string readonly = dir.file("readonly.db");
    fs::copy_file(good, readonly);
    fs::permissions(readonly,
                    fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);

    struct Case {
        std::string path;
        std::string code;
        bool unprivileged;
    };
    const std::vector<Case> cases = {{dir.file(""), "store_is_directory", false},
                                     {text, "store_not_a_database", false},
                                     {truncated, "store_corrupt", false},
                                     {newer, "store_newer_schema", false},
                                     {readonly, "store_read_only", true}};
    for (const Case& c : cases) {
        const std::string before = fs::is_regular_file(c.path) ? read_bytes(c.path) : "";
        const Refusal r = start_refused(c.path, c.unprivileged);
        EXPECT_EQ(r.exit, 2) << c.path << ": " << r.out;
        EXPECT_EQ(r.out.rfind("carrom-server: " + c.code + ": ", 0), 0U) << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
        if (fs::is_regular_file(c.path)) {
            EXPECT_EQ(read_bytes(c.path), before) << c.path;
        }
    }
}

TEST(StoreProcess, WriteFailuresDegradeTheServerAndTheMatchesGoOn) {
    SharedTempDir dir;
    const std::string fail = dir.file("fail");
    ServerProcess server(server_options(dir.file("c.db"), {"CARROM_TEST_STORE_FAIL_FILE=" + fail}));
    ASSERT_NE(server.port(), 0);
    EXPECT_EQ(server.get("/healthz").body, "ok\n");
    const int count = 6;
    auto matches = std::async(std::launch::async,
                              [&] { return play_matches(server.url(), short_matches(count)); });
    std::this_thread::sleep_for(300ms);
    std::ofstream(fail) << "fail\n";
    bool degraded = false;
    for (int i = 0; i < 100 && !degraded; ++i) {
        degraded = server.get("/healthz").body.starts_with("degraded");
        std::this_thread::sleep_for(50ms);
    }
    EXPECT_TRUE(degraded);
    const std::string metrics = server.get("/metrics").body;
    EXPECT_EQ(metrics.find("carrom_store_errors_total 0\n"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("carrom_store_degraded 1\n"), std::string::npos) << metrics;
    std::this_thread::sleep_for(1s); // their strokes wait meanwhile (store_outage_process_test)
    fs::remove(fail);
    const auto runs = matches.get();
    for (const auto& run : runs) {
        EXPECT_TRUE(run.creator.finished && run.joiner.finished) << run.creator.failure;
    }
    bool healthy = false;
    for (int i = 0; i < 200 && !healthy; ++i) {
        healthy = server.get("/healthz").body == "ok\n";
        std::this_thread::sleep_for(50ms);
    }
    EXPECT_TRUE(healthy);
    expect_served_journals_clean(server, count);
}

} // namespace
} // namespace carrom::integration
