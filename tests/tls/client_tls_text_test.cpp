// The refusal sentences of carrom/tls/client_tls.hpp for verification failures the process
// tests cannot easily produce (a certificate not yet valid, an expired intermediate, another
// reason), and for handshakes that end without a verification failure.
#include "carrom/tls/client_tls.hpp"

#include <boost/asio/ssl/error.hpp>
#include <boost/beast/core/error.hpp>
#include <gtest/gtest.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509_vfy.h>

namespace carrom::tls_test {
namespace {

tls::VerifyFailure failure(long error, int depth) {
    tls::VerifyFailure f;
    f.error = error;
    f.depth = depth;
    f.certificate.not_before = "2030-01-01T00:00:00Z";
    f.certificate.not_after = "2020-12-31T00:00:00Z";
    f.certificate.names = {"play.example.org", "192.0.2.7"};
    return f;
}

// An error of OpenSSL's SSL library as Asio reports it (ERR_PACK, without its C casts).
boost::system::error_code ssl_error(int reason) {
    const unsigned long packed = static_cast<unsigned long>(ERR_LIB_SSL) << ERR_LIB_OFFSET |
                                 static_cast<unsigned long>(reason);
    return {static_cast<int>(packed), boost::asio::error::get_ssl_category()};
}

const boost::system::error_code kVerifyFailed = ssl_error(SSL_R_CERTIFICATE_VERIFY_FAILED);

TEST(ClientTlsText, NotYetValid) {
    EXPECT_EQ(tls::tls_handshake_error_text("h:1", kVerifyFailed,
                                            failure(X509_V_ERR_CERT_NOT_YET_VALID, 0)),
              "Refused h:1: its certificate is not valid before 2030-01-01T00:00:00Z.");
}

TEST(ClientTlsText, ExpiredIntermediate) {
    EXPECT_EQ(tls::tls_handshake_error_text("h:1", kVerifyFailed,
                                            failure(X509_V_ERR_CERT_HAS_EXPIRED, 1)),
              "Refused h:1: a certificate of its chain expired on 2020-12-31T00:00:00Z.");
}

TEST(ClientTlsText, OtherHostListsTheCertificatesNames) {
    EXPECT_EQ(tls::tls_handshake_error_text("h:1", kVerifyFailed,
                                            failure(X509_V_ERR_IP_ADDRESS_MISMATCH, 0)),
              "Refused h:1: its certificate is for another host (play.example.org, 192.0.2.7), "
              "not for the one this client asked for.");
}

TEST(ClientTlsText, SelfSignedIsUntrusted) {
    EXPECT_EQ(tls::tls_handshake_error_text("h:1", kVerifyFailed,
                                            failure(X509_V_ERR_DEPTH_ZERO_SELF_SIGNED_CERT, 0)),
              "Refused h:1: its certificate is not signed by an authority this client trusts "
              "(self-signed certificate); a private authority is trusted with --ca-file FILE.");
}

TEST(ClientTlsText, AnyOtherReasonIsNamed) {
    EXPECT_EQ(
        tls::tls_handshake_error_text("h:1", kVerifyFailed, failure(X509_V_ERR_CERT_REVOKED, 0)),
        "Refused h:1: its certificate failed verification (certificate revoked).");
}

TEST(ClientTlsText, HandshakesEndedOtherwise) {
    const tls::VerifyFailure none;
    EXPECT_EQ(tls::tls_handshake_error_text("h:1", boost::beast::error::timeout, none),
              "Could not reach h:1: no TLS answer in time.");
    EXPECT_EQ(tls::tls_handshake_error_text("h:1", ssl_error(SSL_R_WRONG_VERSION_NUMBER), none),
              "h:1 answered, but not with TLS (is it a ws:// server?).");
}

} // namespace
} // namespace carrom::tls_test
