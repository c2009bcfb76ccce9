// carrom-server refuses certificate and key files it cannot use at start: one line on stderr
// naming the file and why, exit status 2 (docs/tls.md).
#include "tls_test_support.hpp"

#include "support/command_run.hpp"

#include <gtest/gtest.h>

namespace carrom::tls_test {
namespace {

// carrom-server's stderr and exit status with these files.
test_support::CommandRun start_with(const std::string& cert, const std::string& key) {
    auto run = test_support::run_command(std::string(CARROM_SERVER_PATH) +
                                         " --host 127.0.0.1 --port 0 --data none --tls-cert '" +
                                         cert + "' --tls-key '" + key + "' 2>&1 >/dev/null");
    return run;
}

class TlsStart : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_TRUE(pki_.made()); }
    Pki pki_;
};

// "CERT" and "KEY" in text replaced by the two paths.
std::string with_paths(std::string text, const std::string& cert, const std::string& key) {
    for (const auto& [token, path] : {std::pair{std::string("CERT"), cert}, {"KEY", key}}) {
        if (const auto at = text.find(token); at != std::string::npos) {
            text.replace(at, token.size(), path);
        }
    }
    return text;
}

TEST_F(TlsStart, EveryUnusableFileExits2WithItsLine) {
    struct BadFiles {
        const char* cert;
        const char* key;
        const char* sentence; // after "carrom-server: bad_tls_files: "
    };
    const BadFiles cases[] = {
        {"server.pem", "localhost.key",
         "the TLS certificate in 'CERT' does not match the key in 'KEY'."},
        {"none.pem", "server.key",
         "cannot read the TLS certificate file 'CERT' (No such file or directory)."},
        {"server.pem", "none.key",
         "cannot read the TLS key file 'KEY' (No such file or directory)."},
        {"expired.pem", "expired.key",
         "the TLS certificate in 'CERT' expired on 2020-12-31T00:00:00Z."},
        {"server.key", "server.key", "the TLS certificate file 'CERT' holds no PEM certificate."},
        {"server.pem", "server.pem",
         "the TLS key file 'KEY' holds no unencrypted PEM private key."},
    };
    for (const BadFiles& files : cases) {
        SCOPED_TRACE(std::string(files.cert) + " " + files.key);
        const std::string cert = pki_.file(files.cert);
        const std::string key = pki_.file(files.key);
        const auto run = start_with(cert, key);
        EXPECT_EQ(run.exit, 2);
        EXPECT_EQ(run.out,
                  "carrom-server: bad_tls_files: " + with_paths(files.sentence, cert, key) + "\n");
    }
}

} // namespace
} // namespace carrom::tls_test
