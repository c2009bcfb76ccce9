#include "carrom/tls/client_tls.hpp"

#include <boost/asio/ip/address.hpp>
#include <boost/asio/ssl/error.hpp>
#include <boost/beast/core/error.hpp>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509_vfy.h>

#include <map>
#include <mutex>

namespace carrom::tls {

namespace ssl = boost::asio::ssl;

std::variant<std::shared_ptr<ssl::context>, std::string>
client_tls_context(const std::string& ca_file) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<ssl::context>> contexts;
    std::lock_guard lock(mutex);
    if (const auto it = contexts.find(ca_file); it != contexts.end()) {
        return it->second;
    }
    auto context = std::make_shared<ssl::context>(ssl::context::tls_client);
    SSL_CTX_set_min_proto_version(context->native_handle(), TLS1_2_VERSION);
    boost::system::error_code ec;
    context->set_default_verify_paths(ec);
    if (ec) {
        return "Could not read the system's trusted certificates (" + ec.message() + ").";
    }
    if (!ca_file.empty()) {
        context->load_verify_file(ca_file, ec);
        if (ec) {
            return "Could not read the trusted certificates of --ca-file '" + ca_file +
                   "': it is missing, unreadable or not PEM certificates.";
        }
    }
    context->set_verify_mode(ssl::verify_peer);
    contexts.emplace(ca_file, context);
    return context;
}

bool expect_server_name(ssl_st* ssl, const std::string& host) {
    boost::system::error_code ec;
    const auto address = boost::asio::ip::make_address(host, ec);
    X509_VERIFY_PARAM* param = SSL_get0_param(ssl);
    if (!ec) { // an IP address: no SNI (RFC 6066), the certificate must carry the address
        return X509_VERIFY_PARAM_set1_ip_asc(param, address.to_string().c_str()) == 1;
    }
    X509_VERIFY_PARAM_set_hostflags(param, X509_CHECK_FLAG_NO_PARTIAL_WILDCARDS);
    // SSL_set_tlsext_host_name, without the macro's C cast.
    return SSL_ctrl(ssl, SSL_CTRL_SET_TLSEXT_HOSTNAME, TLSEXT_NAMETYPE_host_name,
                    const_cast<char*>(host.c_str())) == 1 &&
           X509_VERIFY_PARAM_set1_host(param, host.c_str(), host.size()) == 1;
}

bool note_verification(bool preverified, ssl::verify_context& context, VerifyFailure& failure) {
    X509_STORE_CTX* store = context.native_handle();
    if (!preverified && failure.error == X509_V_OK) {
        failure.error = X509_STORE_CTX_get_error(store);
        failure.depth = X509_STORE_CTX_get_error_depth(store);
        failure.certificate = certificate_facts(X509_STORE_CTX_get_current_cert(store));
    }
    return preverified;
}

std::string tls_handshake_error_text(const std::string& authority,
                                     const boost::system::error_code& ec,
                                     const VerifyFailure& failure) {
    const std::string refused = "Refused " + authority + ": ";
    const CertificateFacts& certificate = failure.certificate;
    switch (failure.error) {
    case X509_V_OK:
        break;
    case X509_V_ERR_CERT_HAS_EXPIRED:
        return refused + (failure.depth == 0 ? "its certificate" : "a certificate of its chain") +
               " expired on " + certificate.not_after + ".";
    case X509_V_ERR_CERT_NOT_YET_VALID:
        return refused + (failure.depth == 0 ? "its certificate" : "a certificate of its chain") +
               " is not valid before " + certificate.not_before + ".";
    case X509_V_ERR_HOSTNAME_MISMATCH:
    case X509_V_ERR_IP_ADDRESS_MISMATCH:
        return refused + "its certificate is for another host (" + names_text(certificate) +
               "), not for the one this client asked for.";
    case X509_V_ERR_DEPTH_ZERO_SELF_SIGNED_CERT:
    case X509_V_ERR_SELF_SIGNED_CERT_IN_CHAIN:
    case X509_V_ERR_UNABLE_TO_GET_ISSUER_CERT:
    case X509_V_ERR_UNABLE_TO_GET_ISSUER_CERT_LOCALLY:
    case X509_V_ERR_UNABLE_TO_VERIFY_LEAF_SIGNATURE:
    case X509_V_ERR_CERT_UNTRUSTED:
        return refused + "its certificate is not signed by an authority this client trusts (" +
               X509_verify_cert_error_string(failure.error) +
               "); a private authority is trusted with --ca-file FILE.";
    default:
        return refused + "its certificate failed verification (" +
               X509_verify_cert_error_string(failure.error) + ").";
    }
    if (ec == boost::beast::error::timeout) {
        return "Could not reach " + authority + ": no TLS answer in time.";
    }
    if (ec.category() == boost::asio::error::get_ssl_category() &&
        ERR_GET_REASON(static_cast<unsigned long>(ec.value())) == SSL_R_WRONG_VERSION_NUMBER) {
        return authority + " answered, but not with TLS (is it a ws:// server?).";
    }
    return "The TLS handshake with " + authority + " failed (" + ec.message() + ").";
}

} // namespace carrom::tls
