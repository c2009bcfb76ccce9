// Matches over wss (docs/tls.md): two carrom-bot programs play a whole match through
// carrom-server with a certificate from the test CA while the certificate is replaced and
// SIGHUP sent (the match goes on untouched; new connections get the new certificate), then
// broken and SIGHUP sent (the previous one stays; /healthz says why). Then a restart of the
// server mid-match: the bots reconnect over wss and resume their seats.
#include "tls_test_support.hpp"

#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <thread>

namespace carrom::tls_test {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;
using test_support::ChildProcess;

// The creator's room code from its "room CODE" line on stderr; "" if none within 10 s.
std::string room_code(ChildProcess& creator) {
    const auto line = creator.wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 10s);
    return line ? line->substr(5) : std::string();
}

// carrom_matches of /metrics: games in progress (-1 when unreadable).
long matches_in_progress(const test_support::ServerProcess& server) {
    const std::string body = server.get("/metrics").body;
    const auto at = body.find("\ncarrom_matches ");
    return at == std::string::npos ? -1 : std::stol(body.substr(at + 16));
}

class TlsMatch : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(pki_.made());
        pki_.make_live("server");
    }

    // Two bots in one room, over wss to localhost (creator) and 127.0.0.1 (joiner).
    void start_match(const test_support::ServerProcess& server, std::vector<std::string> extra) {
        const std::string port = std::to_string(server.port());
        std::vector<std::string> common{
            "--ca-file", pki_.file("ca.pem"), "--games", "1", "--strategy",
            "random",    "--think-ms",        "200"};
        common.insert(common.end(), extra.begin(), extra.end());
        auto creator_args = common;
        creator_args.insert(creator_args.end(), {"--create", "--rule-set", "freestyle",
                                                 "--target-points", "20", "--seed", "3"});
        creator_ =
            std::make_unique<ChildProcess>(bot_argv("wss://localhost:" + port, creator_args));
        const std::string code = room_code(*creator_);
        ASSERT_EQ(code.size(), 6u) << creator_->output();
        auto joiner_args = common;
        joiner_args.insert(joiner_args.end(), {"--join", code, "--seed", "4"});
        joiner_ = std::make_unique<ChildProcess>(bot_argv("wss://127.0.0.1:" + port, joiner_args));
        const auto deadline = Clock::now() + 10s;
        while (matches_in_progress(server) != 1 && Clock::now() < deadline) {
            std::this_thread::sleep_for(20ms);
        }
        ASSERT_EQ(matches_in_progress(server), 1);
    }

    // Both bots finished the game cleanly; their summaries.
    std::pair<BotRun, BotRun> finish_match() {
        BotRun a = finish_bot(*creator_);
        BotRun b = finish_bot(*joiner_);
        EXPECT_EQ(a.exit, 0) << a.output;
        EXPECT_EQ(b.exit, 0) << b.output;
        if (a.summary.is_object() && b.summary.is_object()) {
            EXPECT_EQ(a.summary["ok"], true);
            EXPECT_EQ(b.summary["ok"], true);
            EXPECT_EQ(a.summary["games"], 1);
            EXPECT_EQ(a.summary["scores"], b.summary["scores"]);
        }
        return {std::move(a), std::move(b)};
    }

    Pki pki_;
    std::unique_ptr<ChildProcess> creator_;
    std::unique_ptr<ChildProcess> joiner_;
};

TEST_F(TlsMatch, MatchGoesOnAcrossCertificateReloads) {
    auto server = start_tls_server(pki_, {"--time-scale", "25", "--shot-clock", "0"});
    ASSERT_NE(server->port(), 0);
    const std::string ca = pki_.file("ca.pem");
    ASSERT_EQ(served_serial(server->port(), "localhost", ca), "1001");
    EXPECT_EQ(health_tls(*server)["last_reload"], nullptr);
    start_match(*server, {});

    pki_.make_live("renewed");
    kill(server->process().pid(), SIGHUP);
    EXPECT_TRUE(server->wait_log("SIGHUP: TLS certificate reloaded", Clock::now() + 5s))
        << server->log();
    EXPECT_EQ(served_serial(server->port(), "localhost", ca), "1002");
    EXPECT_EQ(served_serial(server->port(), "127.0.0.1", ca), "1002");
    const auto renewed = health_tls(*server);
    EXPECT_EQ(renewed["serial"], "1002");
    EXPECT_EQ(renewed["last_reload"]["ok"], true);

    {
        std::ofstream broken(pki_.file("live.pem"), std::ios::trunc);
        broken << "not a certificate\n";
    }
    kill(server->process().pid(), SIGHUP);
    EXPECT_TRUE(server->wait_log("TLS reload failed", Clock::now() + 5s)) << server->log();
    EXPECT_EQ(served_serial(server->port(), "localhost", ca), "1002");
    const auto kept = health_tls(*server);
    EXPECT_EQ(kept["serial"], "1002");
    EXPECT_EQ(kept["last_reload"]["ok"], false);
    EXPECT_EQ(kept["last_reload"]["error"],
              "the TLS certificate file '" + pki_.file("live.pem") + "' holds no PEM certificate.");
    EXPECT_EQ(matches_in_progress(*server), 1); // the reloads ended nothing

    const auto [a, b] = finish_match();
    EXPECT_EQ(a.summary["resumes"], 0);
    EXPECT_EQ(b.summary["resumes"], 0);
}

TEST_F(TlsMatch, BotsResumeOverWssAfterARestart) {
    test_support::TempDir data("carrom_tls_data");
    auto server =
        start_tls_server(pki_, {"--time-scale", "25", "--shot-clock", "0"}, data.file("carrom.db"));
    ASSERT_NE(server->port(), 0);
    start_match(*server, {"--resume-for", "20"});
    server->terminate(); // close 1012 "restarting": the bots reconnect with their tokens
    ASSERT_TRUE(server->restart()) << server->log();
    const auto [a, b] = finish_match();
    EXPECT_GE(a.summary["resumes"].get<int>(), 1);
    EXPECT_GE(b.summary["resumes"].get<int>(), 1);
}

} // namespace
} // namespace carrom::tls_test
