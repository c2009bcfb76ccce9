#pragma once
// Private to server/src: accepts TCP connections on the server's address and gives each, on its
// own strand, to an HttpSession (plain only) or to a TlsDetectSession (a server with TLS).

#include "server_stream.hpp"

#include <cstdint>
#include <memory>

namespace carrom::server {

struct ServerCore;

class Listener : public std::enable_shared_from_this<Listener> {
public:
    // Binds and listens at once; throws boost::system::system_error when it cannot.
    Listener(ServerCore& core, tcp::endpoint endpoint);

    std::uint16_t port() const;
    void run();  // starts accepting
    void stop(); // closes the acceptor (any thread)

private:
    void do_accept();
    void on_accept(beast::error_code ec, WsSocket socket);

    ServerCore& core_;
    tcp::acceptor acceptor_;
};

} // namespace carrom::server
