#pragma once
// Private to server/src: the server's TLS certificate and key (--tls-cert, --tls-key) as an
// OpenSSL context for new handshakes. reload() (SIGHUP) reads both files again: when they are
// good, handshakes from then on use them; when not, the previous ones stay and the reason is
// kept for the log and /healthz. A connection keeps the context it was made with for its whole
// life, so a reload drops nothing. Thread-safe.
//
// Both files are PEM: the certificate file holds the server's certificate first, then its chain
// (certbot's fullchain.pem); the key file an unencrypted private key (certbot's privkey.pem).
// TLS 1.2 and 1.3 only, with the cipher suites of docs/server.md ("TLS").

#include "carrom/tls/certificate_facts.hpp"

#include <memory>
#include <mutex>
#include <string>
#include <variant>

namespace boost::asio::ssl {
class context;
}

namespace carrom::server {

class TlsContext {
public:
    // Reads and checks both files: readable, PEM, the certificate valid now (not expired, not
    // before its start), the key its own. The context, or the sentence why not.
    static std::variant<std::shared_ptr<TlsContext>, std::string> load(std::string cert_file,
                                                                       std::string key_file);

    // For a new connection's handshake.
    std::shared_ptr<boost::asio::ssl::context> current() const;
    tls::CertificateFacts certificate() const;
    // Reads the files again (keeps the current ones on failure). A sentence for the log.
    struct ReloadResult {
        bool ok = false;
        std::string text;
    };
    ReloadResult reload();
    // {"subject":...,"serial":...,"not_after":...,"names":[...],"last_reload":null or
    // {"at":"...","ok":true} or {"at":"...","ok":false,"error":"..."}}
    std::string health_json() const;

    struct Loaded;

private:
    TlsContext(std::string cert_file, std::string key_file);

    const std::string cert_file_;
    const std::string key_file_;
    mutable std::mutex mutex_;
    std::shared_ptr<boost::asio::ssl::context> context_;
    tls::CertificateFacts certificate_;
    std::string last_reload_json_ = "null";
};

} // namespace carrom::server
