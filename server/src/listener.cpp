#include "listener.hpp"

#include "http_session.hpp"
#include "server_core.hpp"
#include "tls_detect_session.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core/bind_handler.hpp>

namespace carrom::server {

Listener::Listener(ServerCore& core, tcp::endpoint endpoint)
    : core_(core), acceptor_(asio::make_strand(core.ioc)) {
    acceptor_.open(endpoint.protocol());
    acceptor_.set_option(asio::socket_base::reuse_address(true));
    acceptor_.bind(endpoint);
    acceptor_.listen(asio::socket_base::max_listen_connections);
}

std::uint16_t Listener::port() const {
    return acceptor_.local_endpoint().port();
}

void Listener::run() {
    do_accept();
}

void Listener::stop() {
    asio::post(acceptor_.get_executor(), [self = shared_from_this()] {
        beast::error_code ignored;
        self->acceptor_.close(ignored);
    });
}

void Listener::do_accept() {
    acceptor_.async_accept(asio::make_strand(core_.ioc),
                           beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
}

void Listener::on_accept(beast::error_code ec, WsSocket socket) {
    if (ec == asio::error::operation_aborted || !acceptor_.is_open()) {
        return;
    }
    if (!ec) {
        // Snapshots are small and time-critical: send each at once, without Nagle's delay.
        beast::error_code ignored;
        socket.set_option(tcp::no_delay(true), ignored);
        if (core_.tls) {
            std::make_shared<TlsDetectSession>(core_, std::move(socket))->run();
        } else {
            std::make_shared<HttpSession>(core_, ServerStream(std::move(socket)))->run();
        }
    }
    do_accept();
}

} // namespace carrom::server
