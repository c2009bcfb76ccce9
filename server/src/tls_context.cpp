#include "tls_context.hpp"

#include <boost/asio/buffer.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/asio/ssl/error.hpp>
#include <nlohmann/json.hpp>
#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/ssl.h>
#include <openssl/x509.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>

namespace carrom::server {

namespace ssl = boost::asio::ssl;

namespace {

// TLS 1.2 suites of Mozilla's "intermediate" configuration (server-side TLS guidelines, 5.7),
// in its order; TLS 1.3 uses OpenSSL's default suites, which are that configuration's.
constexpr const char* kTls12Ciphers =
    "ECDHE-ECDSA-AES128-GCM-SHA256:ECDHE-RSA-AES128-GCM-SHA256:"
    "ECDHE-ECDSA-AES256-GCM-SHA384:ECDHE-RSA-AES256-GCM-SHA384:"
    "ECDHE-ECDSA-CHACHA20-POLY1305:ECDHE-RSA-CHACHA20-POLY1305:"
    "DHE-RSA-AES128-GCM-SHA256:DHE-RSA-AES256-GCM-SHA384:DHE-RSA-CHACHA20-POLY1305";

struct BioFree {
    void operator()(BIO* bio) const { BIO_free(bio); }
};
struct X509Free {
    void operator()(X509* x) const { X509_free(x); }
};
struct KeyFree {
    void operator()(EVP_PKEY* key) const { EVP_PKEY_free(key); }
};

// The whole file, or the sentence why it cannot be read.
std::variant<std::string, std::string> read_file(const std::string& path, const char* what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return std::variant<std::string, std::string>(
            std::in_place_index<1>, std::string("cannot read the TLS ") + what + " file '" + path +
                                        "' (" + std::strerror(errno) + ").");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return std::variant<std::string, std::string>(std::in_place_index<0>, text.str());
}

// An encrypted key is refused rather than asking for a pass phrase on the terminal.
int no_pass_phrase(char*, int, int, void*) {
    return -1;
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

} // namespace

struct TlsContext::Loaded {
    std::shared_ptr<ssl::context> context;
    tls::CertificateFacts certificate;
};

namespace {

std::variant<TlsContext::Loaded, std::string> load_files(const std::string& cert_file,
                                                         const std::string& key_file) {
    auto cert_text = read_file(cert_file, "certificate");
    if (cert_text.index() == 1) {
        return std::get<1>(cert_text);
    }
    auto key_text = read_file(key_file, "key");
    if (key_text.index() == 1) {
        return std::get<1>(key_text);
    }
    const std::string& cert_pem = std::get<0>(cert_text);
    const std::string& key_pem = std::get<0>(key_text);
    std::unique_ptr<BIO, BioFree> cert_bio(
        BIO_new_mem_buf(cert_pem.data(), static_cast<int>(cert_pem.size())));
    std::unique_ptr<X509, X509Free> cert(
        PEM_read_bio_X509(cert_bio.get(), nullptr, no_pass_phrase, nullptr));
    if (!cert) {
        return "the TLS certificate file '" + cert_file + "' holds no PEM certificate.";
    }
    TlsContext::Loaded loaded;
    loaded.certificate = tls::certificate_facts(cert.get());
    if (X509_cmp_current_time(X509_get0_notAfter(cert.get())) <= 0) {
        return "the TLS certificate in '" + cert_file + "' expired on " +
               loaded.certificate.not_after + ".";
    }
    if (X509_cmp_current_time(X509_get0_notBefore(cert.get())) > 0) {
        return "the TLS certificate in '" + cert_file + "' is not valid before " +
               loaded.certificate.not_before + ".";
    }
    std::unique_ptr<BIO, BioFree> key_bio(
        BIO_new_mem_buf(key_pem.data(), static_cast<int>(key_pem.size())));
    std::unique_ptr<EVP_PKEY, KeyFree> key(
        PEM_read_bio_PrivateKey(key_bio.get(), nullptr, no_pass_phrase, nullptr));
    if (!key) {
        ERR_clear_error();
        return "the TLS key file '" + key_file + "' holds no unencrypted PEM private key.";
    }
    if (X509_check_private_key(cert.get(), key.get()) != 1) {
        ERR_clear_error();
        return "the TLS certificate in '" + cert_file + "' does not match the key in '" + key_file +
               "'.";
    }
    auto context = std::make_shared<ssl::context>(ssl::context::tls_server);
    SSL_CTX* native = context->native_handle();
    context->set_options(ssl::context::default_workarounds | ssl::context::no_sslv2 |
                         ssl::context::no_sslv3 | ssl::context::no_tlsv1 |
                         ssl::context::no_tlsv1_1 | SSL_OP_NO_RENEGOTIATION |
                         SSL_OP_NO_COMPRESSION);
    SSL_CTX_set_min_proto_version(native, TLS1_2_VERSION);
    SSL_CTX_set_dh_auto(native, 1); // OpenSSL's built-in group for the DHE suites
    // A connection between messages holds no TLS read or write buffer (OpenSSL frees them and
    // allocates them again for the next record): at a human pace most connections are idle.
    SSL_CTX_set_mode(native, SSL_MODE_RELEASE_BUFFERS);
    boost::system::error_code ec;
    if (SSL_CTX_set_cipher_list(native, kTls12Ciphers) != 1) {
        ec.assign(static_cast<int>(ERR_get_error()), boost::asio::error::get_ssl_category());
    }
    if (!ec) {
        context->use_certificate_chain(boost::asio::buffer(cert_pem), ec);
    }
    if (!ec && SSL_CTX_use_PrivateKey(native, key.get()) != 1) {
        ec.assign(static_cast<int>(ERR_get_error()), boost::asio::error::get_ssl_category());
    }
    if (ec) {
        ERR_clear_error();
        return "the TLS certificate chain in '" + cert_file + "' cannot be used (" + ec.message() +
               ").";
    }
    loaded.context = std::move(context);
    return loaded;
}

} // namespace

TlsContext::TlsContext(std::string cert_file, std::string key_file)
    : cert_file_(std::move(cert_file)), key_file_(std::move(key_file)) {}

std::variant<std::shared_ptr<TlsContext>, std::string> TlsContext::load(std::string cert_file,
                                                                        std::string key_file) {
    auto loaded = load_files(cert_file, key_file);
    if (auto* error = std::get_if<std::string>(&loaded)) {
        return std::move(*error);
    }
    std::shared_ptr<TlsContext> tls(new TlsContext(std::move(cert_file), std::move(key_file)));
    tls->context_ = std::move(std::get<Loaded>(loaded).context);
    tls->certificate_ = std::move(std::get<Loaded>(loaded).certificate);
    return tls;
}

std::shared_ptr<ssl::context> TlsContext::current() const {
    std::lock_guard lock(mutex_);
    return context_;
}

tls::CertificateFacts TlsContext::certificate() const {
    std::lock_guard lock(mutex_);
    return certificate_;
}

TlsContext::ReloadResult TlsContext::reload() {
    auto loaded = load_files(cert_file_, key_file_);
    nlohmann::json last{{"at", utc_now()}};
    std::lock_guard lock(mutex_);
    if (auto* error = std::get_if<std::string>(&loaded)) {
        last["ok"] = false;
        last["error"] = *error;
        last_reload_json_ = last.dump();
        return {false, "TLS reload failed, the previous certificate stays: " + *error};
    }
    context_ = std::move(std::get<Loaded>(loaded).context);
    certificate_ = std::move(std::get<Loaded>(loaded).certificate);
    last["ok"] = true;
    last_reload_json_ = last.dump();
    return {true, "TLS certificate reloaded: " + certificate_.subject + ", serial " +
                      certificate_.serial + ", valid until " + certificate_.not_after};
}

std::string TlsContext::health_json() const {
    std::lock_guard lock(mutex_);
    nlohmann::json json{{"subject", certificate_.subject},
                        {"serial", certificate_.serial},
                        {"not_after", certificate_.not_after},
                        {"names", certificate_.names},
                        {"last_reload", nlohmann::json::parse(last_reload_json_)}};
    return json.dump();
}

} // namespace carrom::server
