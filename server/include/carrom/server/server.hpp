#pragma once
// The network server: a WebSocket endpoint and plain HTTP (GET /healthz, GET /metrics and, when
// given a StaticSite, the web client's files) on one port, several I/O threads, one strand per
// room and per connection. No Boost in this header.

#include "carrom/server/bot_factory.hpp"
#include "carrom/server/metrics.hpp"
#include "carrom/server/settings.hpp"
#include "carrom/server/static_site.hpp"
#include "store/match_store.hpp"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace carrom::server {

// settings.tls_cert and tls_key cannot be used; what() is the sentence (docs/tls.md).
struct TlsFileError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Why settings.tls_cert and tls_key cannot be used (Server::listen would throw TlsFileError with
// it); empty when they can, or when no TLS is asked for. For a check at start, before anything
// else is logged.
std::string tls_files_problem(const ServerSettings& settings);
// The first --trusted-proxy that is neither an IP address nor a network, as a sentence; "".
std::string trusted_proxies_problem(const ServerSettings& settings);

class Server {
public:
    // bots: makes server-side bot brains; empty = create_room with a bot is "unsupported".
    // web: the files answered to GET and HEAD of any other path than /healthz, /metrics and
    // /matches... (docs/server.md, "HTTP"); null = none (404). store: where match journals go
    // (flushed on shutdown); null = none: matches end with the process, GET /matches answers 503.
    explicit Server(ServerSettings settings, BotFactory bots = {},
                    std::shared_ptr<const StaticSite> web = nullptr,
                    std::shared_ptr<store::MatchStore> store = nullptr);
    ~Server(); // stops and joins the threads
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    // Loads the TLS certificate and key when settings name them (TlsFileError when they cannot
    // be used), binds and listens; returns the bound port (the ephemeral one for port 0). Throws
    // std::runtime_error when the address cannot be bound.
    std::uint16_t listen();
    // Reads the TLS certificate and key again (SIGHUP); on failure the previous ones stay. The
    // sentence for the log; false on failure or without TLS.
    bool reload_tls(std::string& result);
    // Runs the I/O threads in the background (settings.threads of them).
    void start();
    // Graceful stop: stop accepting, send "shutting_down" and close every connection (1012
    // "restarting"); returns once all connections closed or shutdown_grace_s passed, and the
    // threads ended.
    void shutdown();
    // Blocks until SIGINT or SIGTERM, then shutdown(). SIGHUP meanwhile: reload_tls().
    void run_until_signal();

    const Metrics& metrics() const;
    const ServerSettings& settings() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace carrom::server
