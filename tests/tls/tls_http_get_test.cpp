// net::http_get_any_status over https (carrom-client's reads of a wss:// server's players API,
// docs/client.md, "Ratings, leaderboard and my matches"): with the test CA the answer comes with
// its status and body, an error status's too; without it the certificate is refused with the
// TLS sentence; an https:// URL's default port is 443.
#include "tls_test_support.hpp"

#include "carrom/net/http_get.hpp"

#include <gtest/gtest.h>

namespace carrom::tls_test {
namespace {

class TlsHttpGet : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(pki_.made());
        pki_.make_live("server");
        server_ = start_tls_server(pki_);
        ASSERT_NE(server_->port(), 0) << server_->log();
    }

    std::string url(const std::string& path) const {
        return "https://127.0.0.1:" + std::to_string(server_->port()) + path;
    }

    Pki pki_;
    std::unique_ptr<test_support::ServerProcess> server_;
};

TEST_F(TlsHttpGet, WithTheTestCaTheAnswerComesWithItsStatusAndBody) {
    auto got = net::http_get_any_status(url("/players"), {}, pki_.file("ca.pem"));
    ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(got)) << std::get<std::string>(got);
    EXPECT_EQ(std::get<net::HttpResponse>(got).status, 200U);
    EXPECT_EQ(std::get<net::HttpResponse>(got).body, R"({"kept":false})");
}

TEST_F(TlsHttpGet, AnErrorStatusComesWithItsJsonBody) {
    auto got = net::http_get_any_status(url("/players/Asha"), {}, pki_.file("ca.pem"));
    ASSERT_TRUE(std::holds_alternative<net::HttpResponse>(got)) << std::get<std::string>(got);
    EXPECT_EQ(std::get<net::HttpResponse>(got).status, 503U);
    EXPECT_NE(std::get<net::HttpResponse>(got).body.find("\"store_disabled\""), std::string::npos);
}

TEST_F(TlsHttpGet, WithoutTheCaTheCertificateIsRefused) {
    auto got = net::http_get_any_status(url("/players"), {}, "");
    ASSERT_TRUE(std::holds_alternative<std::string>(got));
    EXPECT_NE(std::get<std::string>(got).find("127.0.0.1:" + std::to_string(server_->port())),
              std::string::npos)
        << std::get<std::string>(got);
    EXPECT_NE(std::get<std::string>(got).find("certificate"), std::string::npos)
        << std::get<std::string>(got);
}

TEST(HttpGetUrl, HttpsIsOnlyForTheApiReads) {
    // http_get (--replay URL) keeps to http://; an https:// address without a port is port 443.
    EXPECT_EQ(std::get<std::string>(net::parse_http_url("https://h/x")),
              "The address 'https://h/x' uses https, which is not supported: use http://.");
    auto got = net::http_get_any_status("ftp://h/x", {}, "");
    EXPECT_EQ(std::get<std::string>(got),
              "The address 'ftp://h/x' must start with http:// or https://.");
}

} // namespace
} // namespace carrom::tls_test
