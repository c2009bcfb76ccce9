// Resuming by itself, with real processes: carrom-server as a program, carrom-bot processes
// and tests/support/fault_proxy.py between them, which cuts or stalls every connection on
// command. The server runs with a small --idle-timeout and --grace so each test takes seconds.
#include "carrom/net/connection.hpp"
#include "support/child_process.hpp"
#include "support/server_process.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace carrom::integration {
namespace {

using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + "carrom_reconnect_" + std::to_string(getpid()) + "_" + name;
}

using test_support::ServerProcess;

// carrom-server on 127.0.0.1 (an ephemeral port), no store, with these extra options.
ServerProcess::Options server_options(const std::vector<std::string>& extra) {
    ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.args = {"--time-scale", "25", "--shot-clock", "0", "--log-level", "warn"};
    options.args.insert(options.args.end(), extra.begin(), extra.end());
    return options;
}

// fault_proxy.py in front of a server port; cut() and stall() write its control file.
class FaultProxy {
public:
    explicit FaultProxy(int target_port) : control_(temp_path("control")) {
        const char* source = std::getenv("CARROM_SOURCE_DIR");
        const std::string script =
            std::string(source != nullptr ? source : ".") + "/tests/support/fault_proxy.py";
        process_ = std::make_unique<ChildProcess>(std::vector<std::string>{
            "python3", script, "--target", "127.0.0.1:" + std::to_string(target_port), "--control",
            control_});
        const std::string prefix = "listening on 127.0.0.1:";
        if (auto line =
                process_->wait_line(ChildProcess::Stream::Out, prefix, Clock::now() + 15s)) {
            port_ = std::stoi(line->substr(prefix.size()));
        }
    }
    ~FaultProxy() { std::remove(control_.c_str()); }
    int port() const { return port_; }
    std::string url() const { return "ws://127.0.0.1:" + std::to_string(port_); }
    // Sends the command and waits for the proxy's confirmation.
    bool command(const std::string& what, double seconds) {
        {
            std::ofstream out(control_ + ".tmp");
            out << what << " " << seconds << "\n";
        }
        std::rename((control_ + ".tmp").c_str(), control_.c_str());
        const std::string confirm = what == "cut" ? "cut " : "stalled ";
        return process_->wait_line(ChildProcess::Stream::Out, confirm, Clock::now() + 5s)
            .has_value();
    }
    bool wait_open(std::chrono::seconds timeout) {
        return process_->wait_line(ChildProcess::Stream::Out, "open", Clock::now() + timeout)
            .has_value();
    }

private:
    std::string control_;
    std::unique_ptr<ChildProcess> process_;
    int port_ = 0;
};

// Two carrom-bot processes: one creates a room through `url`, the other joins it.
struct BotPair {
    std::unique_ptr<ChildProcess> creator;
    std::unique_ptr<ChildProcess> joiner;
    std::string code;

    BotPair(const std::string& url, const std::vector<std::string>& extra) {
        // Random shots to 150 points: about 100 strokes, 25 s at --time-scale 25.
        std::vector<std::string> a{CARROM_BOT_PATH,
                                   "--url",
                                   url,
                                   "--create",
                                   "--rule-set",
                                   "freestyle",
                                   "--target-points",
                                   "150",
                                   "--shot-clock",
                                   "0",
                                   "--strategy",
                                   "random",
                                   "--seed",
                                   "3",
                                   "--timeout",
                                   "90"};
        a.insert(a.end(), extra.begin(), extra.end());
        creator = std::make_unique<ChildProcess>(a);
        if (auto line =
                creator->wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s)) {
            code = line->substr(5);
        }
        std::vector<std::string> b{CARROM_BOT_PATH, "--url",  url, "--join",    code, "--strategy",
                                   "random",        "--seed", "4", "--timeout", "90"};
        b.insert(b.end(), extra.begin(), extra.end());
        joiner = std::make_unique<ChildProcess>(b);
    }

    static nlohmann::json summary(ChildProcess& bot) {
        const auto line = bot.wait_line(ChildProcess::Stream::Out, "{", Clock::now() + 120s);
        if (!line) {
            return {};
        }
        return nlohmann::json::parse(*line, nullptr, false);
    }
};

std::string log_of(ChildProcess& p) {
    std::string out;
    for (const auto& line : p.lines(ChildProcess::Stream::Err)) {
        out += line + "\n";
    }
    return out;
}

TEST(Reconnect, SigtermClosesWithRestarting) {
    ServerProcess server(server_options({}));
    ASSERT_NE(server.port(), 0);
    auto connection = net::Connection::open(server.url());
    connection->send(proto::Hello{proto::kProtocolVersion, "Asha", std::nullopt});
    std::vector<proto::ServerMessage> received;
    const auto wait_for = [&](auto done) {
        const auto deadline = Clock::now() + 10s;
        while (!done() && Clock::now() < deadline) {
            connection->wait(50ms);
            for (auto& m : connection->poll()) {
                received.push_back(std::move(m));
            }
        }
        return done();
    };
    ASSERT_TRUE(wait_for([&] {
        return !received.empty() && std::holds_alternative<proto::Welcome>(received.back());
    }));
    server.terminate(); // SIGTERM
    ASSERT_TRUE(
        wait_for([&] { return connection->status().state == net::ConnectionState::Closed; }));
    for (auto& m : connection->poll()) { // what arrived just before the close
        received.push_back(std::move(m));
    }
    const auto status = connection->status();
    EXPECT_EQ(status.close_code, 1012);
    EXPECT_NE(status.detail.find("restarting"), std::string::npos) << status.detail;
    bool told = false;
    for (const auto& m : received) {
        if (const auto* e = std::get_if<proto::Error>(&m)) {
            told = told || e->code == "shutting_down";
        }
    }
    EXPECT_TRUE(told);
}

// Both bots' summaries after a fault: both finished the match, the same scores, one result each,
// and each got `error_code` from the server at least once (none: not checked). More than once is
// allowed: with a 1 s idle timeout a loaded machine can delay a keep-alive pong past it outside
// the fault too, and the bots resume from that as well.
void expect_finished_with_resume(BotPair& bots, const std::string& error_code = "") {
    const auto a = BotPair::summary(*bots.creator);
    const auto b = BotPair::summary(*bots.joiner);
    ASSERT_TRUE(a.is_object()) << log_of(*bots.creator);
    ASSERT_TRUE(b.is_object()) << log_of(*bots.joiner);
    EXPECT_EQ(a["ok"], true) << a.dump() << "\n" << log_of(*bots.creator);
    EXPECT_EQ(b["ok"], true) << b.dump() << "\n" << log_of(*bots.joiner);
    EXPECT_GE(a["resumes"].get<int>(), 1) << a.dump();
    EXPECT_GE(b["resumes"].get<int>(), 1) << b.dump();
    EXPECT_EQ(a["games"], 1);
    EXPECT_EQ(a["scores"], b["scores"]);
    EXPECT_NE(a["result"], b["result"]);
    if (!error_code.empty()) {
        EXPECT_GE(a["errors"].value(error_code, 0), 1) << a.dump();
        EXPECT_GE(b["errors"].value(error_code, 0), 1) << b.dump();
    }
}

TEST(Reconnect, BotsResumeThroughAThreeSecondCut) {
    ServerProcess server(server_options({"--idle-timeout", "1", "--grace", "10"}));
    ASSERT_NE(server.port(), 0);
    FaultProxy proxy(server.port());
    ASSERT_NE(proxy.port(), 0);
    BotPair bots(proxy.url(), {"--resume-for", "12"});
    ASSERT_EQ(bots.code.size(), 6u) << log_of(*bots.creator);
    std::this_thread::sleep_for(1500ms); // mid-match
    ASSERT_TRUE(proxy.command("cut", 3));
    expect_finished_with_resume(bots);
}

TEST(Reconnect, BotsResumeAfterAStallLongerThanTheIdleTimeout) {
    ServerProcess server(server_options({"--idle-timeout", "1", "--grace", "10"}));
    ASSERT_NE(server.port(), 0);
    FaultProxy proxy(server.port());
    ASSERT_NE(proxy.port(), 0);
    BotPair bots(proxy.url(), {"--resume-for", "12"});
    ASSERT_EQ(bots.code.size(), 6u) << log_of(*bots.creator);
    std::this_thread::sleep_for(1500ms);
    ASSERT_TRUE(proxy.command("stall", 3)); // the server's idle timeout ends both connections
    expect_finished_with_resume(bots, "idle_timeout");
}

TEST(Reconnect, BotGivesUpNamingTheSeatWhenTheCutOutlastsItsResumeTime) {
    ServerProcess server(server_options({"--idle-timeout", "1", "--grace", "2"}));
    ASSERT_NE(server.port(), 0);
    FaultProxy proxy(server.port());
    ASSERT_NE(proxy.port(), 0);
    BotPair bots(proxy.url(), {"--resume-for", "2"});
    ASSERT_EQ(bots.code.size(), 6u) << log_of(*bots.creator);
    std::this_thread::sleep_for(1500ms);
    ASSERT_TRUE(proxy.command("cut", 5));
    const auto a = BotPair::summary(*bots.creator);
    ASSERT_TRUE(a.is_object()) << log_of(*bots.creator);
    EXPECT_EQ(a["ok"], false);
    const std::string failure = a["failure"];
    EXPECT_EQ(failure.rfind("Gave up resuming seat 0 in room " + bots.code + " after ", 0), 0u)
        << failure;
    EXPECT_EQ(bots.creator->wait_exit(Clock::now() + 10s), 1);
}

TEST(Reconnect, BotStopsWhenTheServerNoLongerHoldsTheSeat) {
    ServerProcess server(server_options({"--idle-timeout", "1", "--grace", "1"}));
    ASSERT_NE(server.port(), 0);
    FaultProxy proxy(server.port());
    ASSERT_NE(proxy.port(), 0);
    BotPair bots(proxy.url(), {"--resume-for", "15"});
    ASSERT_EQ(bots.code.size(), 6u) << log_of(*bots.creator);
    std::this_thread::sleep_for(1500ms);
    ASSERT_TRUE(proxy.command("cut", 3)); // past the grace: both seats are gone
    const auto a = BotPair::summary(*bots.creator);
    ASSERT_TRUE(a.is_object()) << log_of(*bots.creator);
    EXPECT_EQ(a["ok"], false);
    const std::string failure = a["failure"];
    EXPECT_EQ(failure.rfind("The server no longer holds seat 0 in room " + bots.code, 0), 0u)
        << failure;
    EXPECT_EQ(a["errors"].value("bad_token", 0), 1);
}

TEST(Reconnect, BotsRetryThroughAServerRestartAndStopAtTheLostSeat) {
    // Without a store the restarted server no longer knows the match: close 1012, tries while
    // the port is closed, then bad_token from the new process.
    auto server = std::make_unique<ServerProcess>(server_options({"--grace", "30"}));
    ASSERT_NE(server->port(), 0);
    const int port = server->port();
    BotPair bots(server->url(), {"--resume-for", "30"});
    ASSERT_EQ(bots.code.size(), 6u) << log_of(*bots.creator);
    std::this_thread::sleep_for(1500ms);
    server->terminate(); // SIGTERM
    std::this_thread::sleep_for(1500ms);
    ASSERT_TRUE(server->restart()) << server->log();
    ASSERT_EQ(server->port(), port);
    for (ChildProcess* bot : {bots.creator.get(), bots.joiner.get()}) {
        const auto s = BotPair::summary(*bot);
        ASSERT_TRUE(s.is_object()) << log_of(*bot);
        EXPECT_EQ(s["ok"], false);
        const std::string failure = s["failure"];
        EXPECT_EQ(failure.rfind("The server no longer holds seat ", 0), 0u) << failure;
        EXPECT_NE(failure.find("in room " + bots.code + " (bad_token: "), std::string::npos)
            << failure;
        EXPECT_EQ(s["errors"].value("shutting_down", 0), 1) << s.dump();
        std::string log;
        for (const auto& line : bot->lines(ChildProcess::Stream::Err)) { // spdlog: stderr
            log += line + "\n";
        }
        EXPECT_NE(log.find("code 1012: the server is restarting"), std::string::npos) << log;
    }
}

} // namespace
} // namespace carrom::integration
