#pragma once
// Private to server/src: a new connection on a server with a TLS certificate. Reads the first
// bytes (Beast's TLS detection): a TLS ClientHello gets the TLS handshake with the certificate
// current at that moment, then an HttpSession over TLS (https, wss); anything else a plain
// HttpSession given the bytes read. Both steps together must end within
// settings.tls_handshake_timeout_s (else the socket is closed), and until they end the
// connection counts in its address's open connections (settings.max_connections_per_address):
// connections that never finish a handshake cost a bounded number of sockets per address, for a
// bounded time.

#include "server_stream.hpp"

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>

#include <memory>
#include <string>

namespace carrom::server {

struct ServerCore;

class TlsDetectSession : public std::enable_shared_from_this<TlsDetectSession> {
public:
    TlsDetectSession(ServerCore& core, WsSocket socket);
    ~TlsDetectSession();

    void run();

private:
    void on_detect(beast::error_code ec, bool tls);
    void on_handshake(beast::error_code ec, std::size_t used);
    // Stops the deadline and the address count: the connection goes on as an HttpSession.
    void hand_over();
    // The deadline passed: counts a handshake under way as failed, frees the address's count,
    // then closes the socket (in that order, so a peer that sees the close sees the counts).
    void time_out();
    void release_address();

    ServerCore& core_;
    ServerStream stream_;
    beast::flat_buffer buffer_;
    asio::steady_timer deadline_;
    std::string address_;
    bool address_counted_ = false;
    bool handshaking_ = false; // between async_handshake and on_handshake
    bool timed_out_ = false;
    bool handed_over_ = false; // stream_ moved into an HttpSession
};

} // namespace carrom::server
