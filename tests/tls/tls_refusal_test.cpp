// carrom-bot refuses a server whose certificate it cannot trust, with the sentence of
// carrom/tls/client_tls.hpp in its JSON summary (docs/bots.md): signed by an authority it does
// not trust, for another host, expired; and says so when wss:// meets a plain server or
// --ca-file cannot be read. A trusted certificate for the host connects.
#include "tls_test_support.hpp"

#include <gtest/gtest.h>

namespace carrom::tls_test {
namespace {

using Clock = std::chrono::steady_clock;

class TlsRefusal : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(pki_.made()); }

    // The bot's failure sentence against url (it must fail).
    std::string refusal(const std::string& url, std::vector<std::string> args) {
        args.insert(args.end(), {"--quick", "--resume-for", "0"});
        const BotRun run = run_bot(url, std::move(args));
        EXPECT_NE(run.exit, 0) << run.output;
        if (!run.summary.is_object()) {
            ADD_FAILURE() << "no summary: " << run.output;
            return {};
        }
        EXPECT_EQ(run.summary["ok"], false);
        return run.summary["failure"].get<std::string>();
    }

    Pki pki_;
};

TEST_F(TlsRefusal, UntrustedAuthorityIsRefused) {
    pki_.make_live("server");
    auto server = start_tls_server(pki_);
    ASSERT_NE(server->port(), 0);
    const std::string url = "wss://127.0.0.1:" + std::to_string(server->port());
    const std::string sentence =
        "Refused 127.0.0.1:" + std::to_string(server->port()) +
        ": its certificate is not signed by an authority this client trusts (unable to get local "
        "issuer certificate); a private authority is trusted with --ca-file FILE.";
    EXPECT_EQ(refusal(url, {}), sentence); // the system's store only
    EXPECT_EQ(refusal(url, {"--ca-file", pki_.file("other-ca.pem")}), sentence);
}

TEST_F(TlsRefusal, CertificateForAnotherHostIsRefused) {
    pki_.make_live("localhost"); // for localhost only
    auto server = start_tls_server(pki_);
    ASSERT_NE(server->port(), 0);
    const std::string port = std::to_string(server->port());
    EXPECT_EQ(refusal("wss://127.0.0.1:" + port, {"--ca-file", pki_.file("ca.pem")}),
              "Refused 127.0.0.1:" + port +
                  ": its certificate is for another host (localhost), not for the one this "
                  "client asked for.");
    EXPECT_EQ(served_serial(server->port(), "localhost", pki_.file("ca.pem")), "1003");
    EXPECT_EQ(served_serial(server->port(), "127.0.0.1", pki_.file("ca.pem")), "");
}

TEST_F(TlsRefusal, ExpiredCertificateIsRefused) {
    // carrom-server refuses to serve an expired certificate: openssl's test server serves it.
    test_support::ChildProcess server({"openssl", "s_server", "-www", "-accept", "127.0.0.1:0",
                                       "-cert", pki_.file("expired.pem"), "-key",
                                       pki_.file("expired.key")});
    const auto line =
        server.wait_line(test_support::ChildProcess::Stream::Out,
                         "ACCEPT 127.0.0.1:", Clock::now() + std::chrono::seconds(10));
    ASSERT_TRUE(line) << server.output();
    const std::string port = line->substr(line->rfind(':') + 1);
    EXPECT_EQ(refusal("wss://127.0.0.1:" + port, {"--ca-file", pki_.file("ca.pem")}),
              "Refused 127.0.0.1:" + port + ": its certificate expired on 2020-12-31T00:00:00Z.");
}

TEST_F(TlsRefusal, WssToAPlainServerSaysSo) {
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    test_support::ServerProcess server(options);
    ASSERT_NE(server.port(), 0);
    const std::string port = std::to_string(server.port());
    EXPECT_EQ(refusal("wss://127.0.0.1:" + port, {"--ca-file", pki_.file("ca.pem")}),
              "127.0.0.1:" + port + " answered, but not with TLS (is it a ws:// server?).");
}

TEST_F(TlsRefusal, UnreadableCaFileSaysSo) {
    EXPECT_EQ(refusal("wss://127.0.0.1:9", {"--ca-file", pki_.file("none.pem")}),
              "Could not read the trusted certificates of --ca-file '" + pki_.file("none.pem") +
                  "': it is missing, unreadable or not PEM certificates.");
}

} // namespace
} // namespace carrom::tls_test
