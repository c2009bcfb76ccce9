#include "support/tcp_listener.hpp"

#include <sys/socket.h>
#include <sys/time.h>

namespace carrom::test_support {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

TcpListener::TcpListener(const std::string& address, Serve serve)
    : acceptor_(ioc_, tcp::endpoint(asio::ip::make_address(address), 0)) {
    port_ = acceptor_.local_endpoint().port();
    thread_ = std::thread([this, serve = std::move(serve)] {
        while (!stopping_) {
            tcp::socket socket(ioc_);
            boost::system::error_code ec;
            acceptor_.accept(socket, ec);
            if (ec || stopping_) {
                return;
            }
            ++accepted_;
            const timeval limit{5, 0}; // every blocking read of `serve` ends within 5 s
            ::setsockopt(socket.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof(limit));
            if (serve) {
                serve(socket);
            }
        }
    });
}

TcpListener::~TcpListener() {
    stopping_ = true;
    ::shutdown(acceptor_.native_handle(), SHUT_RDWR); // wakes a pending accept
    thread_.join();
}

} // namespace carrom::test_support
