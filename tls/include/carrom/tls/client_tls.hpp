#pragma once
// The client side of TLS (carrom-client, carrom-bot through net/, carrom-load): the server's
// certificate is verified against the system's CA store (Debian's ca-certificates) and, when
// given, one more file of trusted certificates (--ca-file), with the host name or IP address of
// the URL checked against it. There is no way to skip the check. A refused certificate gets a
// sentence that names why (untrusted, expired, another host).

#include "carrom/tls/certificate_facts.hpp"
#include "carrom/tls/flex_stream.hpp"

#include <boost/asio/ssl/verify_context.hpp>
#include <boost/system/error_code.hpp>

#include <memory>
#include <string>
#include <variant>

struct ssl_st; // OpenSSL's SSL

namespace carrom::tls {

// The first certificate the verification refused (error 0: none was refused).
struct VerifyFailure {
    long error = 0; // OpenSSL's X509_V_ERR_...
    int depth = 0;  // 0: the server's own certificate, 1: its issuer, ...
    CertificateFacts certificate;
};

// The context every client connection shares (one per ca_file; "" = the system's store only),
// or the sentence why it cannot be made (an unreadable --ca-file). Thread-safe.
std::variant<std::shared_ptr<boost::asio::ssl::context>, std::string>
client_tls_context(const std::string& ca_file);

// On a new client TLS stream: SNI (for a host name, not an IP address) and the name the server's
// certificate must carry. False when OpenSSL refuses the name.
bool expect_server_name(ssl_st* ssl, const std::string& host);
// The verify callback: records the first refusal in failure; returns preverified.
bool note_verification(bool preverified, boost::asio::ssl::verify_context& context,
                       VerifyFailure& failure);

// Turns stream (connected) into a TLS client stream for host; failure gets the refusal, if any,
// during the handshake that follows (tls().async_handshake(client, ...)). failure must outlive
// the handshake.
template <class Next>
bool start_client_tls(FlexStream<Next>& stream, std::shared_ptr<boost::asio::ssl::context> context,
                      const std::string& host, VerifyFailure& failure) {
    stream.use_tls(std::move(context));
    auto& tls_stream = stream.tls();
    tls_stream.set_verify_callback(
        [&failure](bool preverified, boost::asio::ssl::verify_context& verify) {
            return note_verification(preverified, verify, failure);
        });
    return expect_server_name(tls_stream.native_handle(), host);
}

// The sentence for a TLS handshake with authority (HOST:PORT) that failed with ec; failure says
// which certificate was refused and why, e.g. "Refused 127.0.0.1:7777: its certificate expired
// on 2026-01-01T00:00:00Z."
std::string tls_handshake_error_text(const std::string& authority,
                                     const boost::system::error_code& ec,
                                     const VerifyFailure& failure);

} // namespace carrom::tls
