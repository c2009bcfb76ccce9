// carrom-server refuses certificate and key files it cannot use at start: one line on stderr
// naming the file and why, exit status 2 (docs/server.md, "TLS").
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

TEST_F(TlsStart, KeyOfAnotherCertificateExits2) {
    const auto run = start_with(pki_.file("server.pem"), pki_.file("localhost.key"));
    EXPECT_EQ(run.exit, 2);
    EXPECT_EQ(run.out, "carrom-server: bad_tls_files: the TLS certificate in '" +
                           pki_.file("server.pem") + "' does not match the key in '" +
                           pki_.file("localhost.key") + "'.\n");
}

TEST_F(TlsStart, MissingCertificateFileExits2) {
    const auto run = start_with(pki_.file("none.pem"), pki_.file("server.key"));
    EXPECT_EQ(run.exit, 2);
    EXPECT_EQ(run.out, "carrom-server: bad_tls_files: cannot read the TLS certificate file '" +
                           pki_.file("none.pem") + "' (No such file or directory).\n");
}

TEST_F(TlsStart, ExpiredCertificateExits2) {
    const auto run = start_with(pki_.file("expired.pem"), pki_.file("expired.key"));
    EXPECT_EQ(run.exit, 2);
    EXPECT_EQ(run.out, "carrom-server: bad_tls_files: the TLS certificate in '" +
                           pki_.file("expired.pem") + "' expired on 2020-12-31T00:00:00Z.\n");
}

TEST_F(TlsStart, KeyGivenAsCertificateExits2) {
    const auto run = start_with(pki_.file("server.key"), pki_.file("server.key"));
    EXPECT_EQ(run.exit, 2);
    EXPECT_EQ(run.out, "carrom-server: bad_tls_files: the TLS certificate file '" +
                           pki_.file("server.key") + "' holds no PEM certificate.\n");
}

TEST_F(TlsStart, CertificateGivenAsKeyExits2) {
    const auto run = start_with(pki_.file("server.pem"), pki_.file("server.pem"));
    EXPECT_EQ(run.exit, 2);
    EXPECT_EQ(run.out, "carrom-server: bad_tls_files: the TLS key file '" +
                           pki_.file("server.pem") + "' holds no unencrypted PEM private key.\n");
}

} // namespace
} // namespace carrom::tls_test
