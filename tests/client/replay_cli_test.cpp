// carrom-client --replay as a program (under Xvfb when there is no display): a journal from a
// file, from a real carrom-server's HTTP port (its --web-root serving the file) and from the
// server's GET /matches/ID after two carrom-bots played a match plays to the end and writes the
// journal's replayed final state; journals it cannot replay exit 2 with one
// line. And net::http_get against the same server: a file, 404, a refused connection, a body over
// the limit, a listener that never answers.

#include "carrom/net/http_get.hpp"
#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "client_program.hpp"
#include "proto/journal_support.hpp"
#include "support/child_process.hpp"
#include "support/server_process.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;
namespace fs = std::filesystem;

struct ReplayDir {
    fs::path path;
    explicit ReplayDir(const std::string& name)
        : path(fs::temp_directory_path() /
               ("carrom-replay-" + name + "-" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~ReplayDir() { fs::remove_all(path); }
};

void write_file(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A short seeded game that ends (seat 1 forfeits after a few strokes when no one has won).
const proto::MatchJournal& short_journal() {
    static const proto::MatchJournal journal =
        proto::test::random_game(rules::RuleSet::Icf, 5, 6).journal();
    return journal;
}

using test_support::ServerProcess;

// carrom-server serving `root` over HTTP on an ephemeral port of 127.0.0.1; data: the match
// store's file, or "none".
ServerProcess::Options web_server(const fs::path& root, const std::string& data = "none") {
    ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.data = data;
    options.args = {"--log-level", "warn", "--time-scale", "25", "--web-root", root.string()};
    return options;
}

struct ClientRun {
    int exit_code = -1;
    std::string out;
    std::string err;
};

ClientRun run_client(const std::vector<std::string>& args) {
    ChildProcess client(client_argv(args), {client_asan_options()});
    ClientRun run;
    run.exit_code = client.wait_exit(Clock::now() + 180s).value_or(-1);
    for (const auto& l : client.lines(ChildProcess::Stream::Out)) {
        run.out += l + "\n";
    }
    for (const auto& l : client.lines(ChildProcess::Stream::Err)) {
        run.err += l + "\n";
    }
    return run;
}

// The final state the client wrote equals the journal's replayed final state.
// reason: game_end's reason as the client wrote it; nothing: not checked.
void expect_final_state(const fs::path& file, const proto::MatchJournal& journal,
                        const std::optional<std::string>& reason = "forfeit") {
    const proto::ReplayResult replayed = proto::replay(journal);
    ASSERT_TRUE(replayed.ok());
    ASSERT_TRUE(replayed.state.result);
    const auto j = nlohmann::json::parse(read_all(file), nullptr, false);
    ASSERT_TRUE(j.is_object()) << read_all(file);
    EXPECT_EQ(j["room"], journal.created.room_code);
    EXPECT_EQ(j["you"], -1);
    const auto& result = *replayed.state.result;
    EXPECT_EQ(j["winner"], result.winner_team ? *result.winner_team : -1);
    if (reason) {
        EXPECT_EQ(j["reason"], *reason); // short_journal: grace_expired, as the room reports it
    }
    EXPECT_EQ(j["scores"], nlohmann::json(replayed.state.scores));
    std::size_t pieces = 0;
    for (const auto& b : j["bodies"]) {
        const int id = b["id"];
        if (id == kStrikerId) {
            continue;
        }
        const Body& expected = replayed.state.bodies.at(static_cast<std::size_t>(id));
        EXPECT_EQ(b["pocketed"], expected.pocketed) << id;
        if (!expected.pocketed) {
            EXPECT_NEAR(b["x"].get<double>(), expected.pos_px.x, 0.005) << id;
            EXPECT_NEAR(b["y"].get<double>(), expected.pos_px.y, 0.005) << id;
        }
        ++pieces;
    }
    EXPECT_EQ(pieces, replayed.state.bodies.size());
}

TEST(ReplayCli, AJournalFilePlaysToTheEndAndWritesItsReplayedFinalState) {
    ReplayDir dir("file");
    write_file(dir.path / "match.json", proto::journal_to_json(short_journal()).dump());
    const fs::path final_state = dir.path / "final.json";
    const ClientRun run = run_client({"--replay", (dir.path / "match.json").string(),
                                      "--replay-speed", "4", "--final-state", final_state.string(),
                                      "--timeout", "150", "--width", "500", "--height", "500"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("final state"), std::string::npos) << run.out;
    expect_final_state(final_state, short_journal());
}

// --replay-at past the end opens the replay finished: the same final state, game_end's reason
// included (the outcomes jumped over reach the HUD too).
TEST(ReplayCli, OpenedAtTheEndItWritesTheSameFinalState) {
    ReplayDir dir("end");
    write_file(dir.path / "match.json", proto::journal_to_json(short_journal()).dump());
    const fs::path final_state = dir.path / "final.json";
    const ClientRun run = run_client({"--replay", (dir.path / "match.json").string(), "--replay-at",
                                      "100000", "--final-state", final_state.string(), "--timeout",
                                      "60", "--width", "400", "--height", "400"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    expect_final_state(final_state, short_journal());
}

// The replay window holds the match window's unattended modes: --timeout ends it with code 3
// saying where the replay was.
TEST(ReplayCli, ATimeoutEndsItWithCodeThreeSayingWhereTheReplayWas) {
    ReplayDir dir("timeout");
    write_file(dir.path / "match.json", proto::journal_to_json(short_journal()).dump());
    const ClientRun run =
        run_client({"--replay", (dir.path / "match.json").string(), "--replay-at", "1", "--timeout",
                    "0.5", "--width", "300", "--height", "300"});
    EXPECT_EQ(run.exit_code, 3) << run.err;
    // A line of its own (SFML may write before it).
    EXPECT_NE(("\n" + run.err).find("\ncarrom-client: gave up after 0.5 s (replay at 1 of "),
              std::string::npos)
        << run.err;
}

// --screenshot with --report: the PNG and, as for a match, what it shows (the replay's pieces).
TEST(ReplayCli, AScreenshotWithAReportShowsTheReplayedPieces) {
    ReplayDir dir("shot");
    write_file(dir.path / "match.json", proto::journal_to_json(short_journal()).dump());
    const fs::path png = dir.path / "replay.png";
    const fs::path report = dir.path / "report.json";
    const ClientRun run =
        run_client({"--replay", (dir.path / "match.json").string(), "--replay-at", "100000",
                    "--screenshot", png.string(), "--frames", "3", "--report", report.string(),
                    "--timeout", "60", "--width", "400", "--height", "400"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("saved " + png.string()), std::string::npos) << run.out;
    EXPECT_GT(fs::file_size(png), 0u);
    const proto::ReplayResult replayed = proto::replay(short_journal());
    ASSERT_TRUE(replayed.ok());
    std::vector<int> on_board;
    for (const Body& b : replayed.state.bodies) {
        if (!b.pocketed && b.id != kStrikerId) {
            on_board.push_back(b.id);
        }
    }
    const auto j = nlohmann::json::parse(read_all(report), nullptr, false);
    ASSERT_TRUE(j.is_object()) << read_all(report);
    EXPECT_EQ(j["room"], short_journal().created.room_code);
    std::vector<int> drawn;
    for (const auto& b : j["bodies"]) {
        if (b["id"] != kStrikerId) {
            drawn.push_back(b["id"]);
        }
    }
    EXPECT_EQ(drawn, on_board);
}

TEST(ReplayCli, AJournalFromAServersHttpPortPlaysTheSame) {
    ReplayDir dir("url");
    write_file(dir.path / "index.html", "<!doctype html><title>carrom</title>");
    write_file(dir.path / "m-0001.json", proto::journal_to_json(short_journal()).dump());
    ServerProcess server(web_server(dir.path));
    ASSERT_NE(server.port(), 0);
    const fs::path final_state = dir.path / "final.json";
    const ClientRun run = run_client({"--replay", server.base() + "/m-0001.json", "--replay-speed",
                                      "4", "--final-state", final_state.string(), "--timeout",
                                      "150", "--width", "500", "--height", "500"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    expect_final_state(final_state, short_journal());
}

// A match two carrom-bots played through carrom-server --data, replayed from the server's own
// GET /matches/ID: the client ends on the state the journal replays to.
TEST(ReplayCli, AMatchFromTheServersMatchApiPlaysToItsFinalState) {
    ReplayDir dir("api");
    write_file(dir.path / "index.html", "<!doctype html><title>carrom</title>");
    ServerProcess server(web_server(dir.path, (dir.path / "c.db").string()));
    ASSERT_NE(server.port(), 0);
    const std::vector<std::string> common{"--shot-clock", "0",  "--strategy", "random",
                                          "--timeout",    "90", "--games",    "1"};
    std::vector<std::string> creator{
        CARROM_BOT_PATH, "--url",      server.url(), "--name",          "Ann", "--seed", "4",
        "--create",      "--rule-set", "freestyle",  "--target-points", "60"};
    creator.insert(creator.end(), common.begin(), common.end());
    ChildProcess ann(creator);
    const auto room = ann.wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s);
    ASSERT_TRUE(room);
    std::vector<std::string> joiner{CARROM_BOT_PATH, "--url", server.url(), "--name",       "Ben",
                                    "--seed",        "5",     "--join",     room->substr(5)};
    joiner.insert(joiner.end(), common.begin(), common.end());
    ChildProcess ben(joiner);
    EXPECT_EQ(ann.wait_exit(Clock::now() + 100s).value_or(-1), 0);
    EXPECT_EQ(ben.wait_exit(Clock::now() + 20s).value_or(-1), 0);

    const auto listed = net::http_get(server.base() + "/matches?player=Ann&limit=1", {});
    ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(listed)) << std::get<std::string>(listed);
    const auto list = nlohmann::json::parse(std::get<net::HttpResponse>(listed).body);
    ASSERT_EQ(list["matches"].size(), 1U) << list.dump();
    const std::string url =
        server.base() + "/matches/" + list["matches"][0]["id"].get<std::string>();
    const auto fetched = net::http_get(url, {});
    ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(fetched));
    const auto journal = proto::decode_journal_text(std::get<net::HttpResponse>(fetched).body);
    ASSERT_TRUE(journal.ok());

    const fs::path final_state = dir.path / "final.json";
    const ClientRun run =
        run_client({"--replay", url, "--replay-speed", "4", "--final-state", final_state.string(),
                    "--timeout", "150", "--width", "500", "--height", "500"});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    expect_final_state(final_state, journal.value, std::nullopt);
}

// Exit code 2 and one line on stderr holding `needle`; no window needed.
void expect_refused(const std::vector<std::string>& args, const std::string& needle) {
    std::vector<std::string> argv{CARROM_CLIENT_PATH};
    argv.insert(argv.end(), args.begin(), args.end());
    ChildProcess client(argv);
    EXPECT_EQ(client.wait_exit(Clock::now() + 30s).value_or(-1), 2);
    const auto& err = client.lines(ChildProcess::Stream::Err);
    ASSERT_EQ(err.size(), 1U) << (err.empty() ? "" : err.back());
    EXPECT_NE(err[0].find(needle), std::string::npos) << err[0];
    EXPECT_EQ(err[0].rfind("carrom-client: ", 0), 0U) << err[0];
}

TEST(ReplayCli, JournalsItCannotReplayExitTwoWithOneLine) {
    ReplayDir dir("bad");
    write_file(dir.path / "broken.json", "{\"format\": 1, \"match\": ");
    expect_refused({"--replay", (dir.path / "broken.json").string()}, "(malformed_json)");

    proto::MatchJournal other = short_journal();
    other.created.versions.rules += 1;
    write_file(dir.path / "other.json", proto::journal_to_json(other).dump());
    expect_refused({"--replay", (dir.path / "other.json").string()},
                   proto::check_versions(other.created)->message);

    expect_refused({"--replay", (dir.path / "missing.json").string()}, "cannot read");
    // "-": standard input.
    {
        ChildProcess client({"/bin/sh", "-c",
                             std::string(CARROM_CLIENT_PATH) + " --replay - < " +
                                 (dir.path / "broken.json").string()});
        EXPECT_EQ(client.wait_exit(Clock::now() + 30s).value_or(-1), 2);
        const auto& err = client.lines(ChildProcess::Stream::Err);
        ASSERT_EQ(err.size(), 1U);
        EXPECT_EQ(err[0].rfind("carrom-client: standard input: ", 0), 0U) << err[0];
        EXPECT_NE(err[0].find("(malformed_json)"), std::string::npos) << err[0];
    }
    expect_refused({"--replay", "http://127.0.0.1:1/m-0001"}, "connection refused");
}

// http_get against carrom-server's static files.
class HttpGet : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new ReplayDir("http");
        write_file(dir_->path / "index.html", "<!doctype html><title>carrom</title>");
        write_file(dir_->path / "big.json", std::string(5000, ' ') + "{}");
        server_ = new ServerProcess(web_server(dir_->path));
    }
    static void TearDownTestSuite() {
        delete server_;
        delete dir_;
    }
    static ReplayDir* dir_;
    static ServerProcess* server_;
};
ReplayDir* HttpGet::dir_ = nullptr;
ServerProcess* HttpGet::server_ = nullptr;

TEST_F(HttpGet, AFileComesBackWhole) {
    ASSERT_NE(server_->port(), 0);
    auto got = net::http_get(server_->base() + "/big.json", {});
    ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(got)) << std::get<std::string>(got);
    EXPECT_EQ(std::get<net::HttpResponse>(got).status, 200U);
    EXPECT_EQ(std::get<net::HttpResponse>(got).body, std::string(5000, ' ') + "{}");
}

TEST_F(HttpGet, AMissingFileIsA404Sentence) {
    ASSERT_NE(server_->port(), 0);
    auto got = net::http_get(server_->base() + "/matches-nowhere.json", {});
    ASSERT_TRUE(std::holds_alternative<std::string>(got));
    EXPECT_NE(std::get<std::string>(got).find("answered 404"), std::string::npos)
        << std::get<std::string>(got);
}

TEST_F(HttpGet, ABodyOverTheLimitIsRefused) {
    ASSERT_NE(server_->port(), 0);
    net::HttpLimits limits;
    limits.max_body_bytes = 1000;
    auto got = net::http_get(server_->base() + "/big.json", limits);
    ASSERT_TRUE(std::holds_alternative<std::string>(got))
        << std::get<net::HttpResponse>(got).body.size();
    EXPECT_NE(std::get<std::string>(got).find("more than 1000 bytes"), std::string::npos)
        << std::get<std::string>(got);
}

TEST(HttpGetErrors, ARefusedConnectionAndASilentListenerAreSentences) {
    // A port nothing listens on: bound, then closed.
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    ASSERT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len), 0);
    const std::string closed = "http://127.0.0.1:" + std::to_string(ntohs(addr.sin_port)) + "/x";
    ::close(fd);
    auto got = net::http_get(closed, {});
    ASSERT_TRUE(std::holds_alternative<std::string>(got));
    EXPECT_NE(std::get<std::string>(got).find("connection refused"), std::string::npos)
        << std::get<std::string>(got);

    // A listener that accepts (in the kernel) and never answers.
    fd = ::socket(AF_INET, SOCK_STREAM, 0);
    addr.sin_port = 0;
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
    ASSERT_EQ(::listen(fd, 4), 0);
    ASSERT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len), 0);
    net::HttpLimits limits;
    limits.timeout = 300ms;
    const auto t0 = Clock::now();
    got = net::http_get("http://127.0.0.1:" + std::to_string(ntohs(addr.sin_port)) + "/x", limits);
    EXPECT_LT(Clock::now() - t0, 3s);
    ::close(fd);
    ASSERT_TRUE(std::holds_alternative<std::string>(got));
    EXPECT_NE(std::get<std::string>(got).find("did not answer within 300 ms"), std::string::npos)
        << std::get<std::string>(got);

    got = net::http_get("https://127.0.0.1/x", {});
    ASSERT_TRUE(std::holds_alternative<std::string>(got));
    EXPECT_NE(std::get<std::string>(got).find("https, which is not supported"), std::string::npos);
}

TEST(HttpGetErrors, AddressesParseWithPort80ByDefault) {
    auto url = net::parse_http_url("http://example.org/matches/m-1");
    ASSERT_TRUE(std::holds_alternative<net::WsUrl>(url));
    EXPECT_EQ(std::get<net::WsUrl>(url).host, "example.org");
    EXPECT_EQ(std::get<net::WsUrl>(url).port, 80);
    EXPECT_EQ(std::get<net::WsUrl>(url).target, "/matches/m-1");
    url = net::parse_http_url("http://[::1]:7777");
    ASSERT_TRUE(std::holds_alternative<net::WsUrl>(url));
    EXPECT_EQ(std::get<net::WsUrl>(url).host, "::1");
    EXPECT_EQ(std::get<net::WsUrl>(url).port, 7777);
    EXPECT_EQ(std::get<net::WsUrl>(url).target, "/");
    EXPECT_TRUE(std::holds_alternative<std::string>(net::parse_http_url("http://:80/")));
    EXPECT_TRUE(std::holds_alternative<std::string>(net::parse_http_url("ws://h:80/")));
    EXPECT_TRUE(std::holds_alternative<std::string>(net::parse_http_url("http://h:99999/")));
}

} // namespace
} // namespace carrom::client
