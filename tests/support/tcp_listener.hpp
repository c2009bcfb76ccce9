#pragma once
// A TCP listener for tests on an ephemeral port of a loopback address: it accepts connections
// one at a time on its own thread until destroyed, counts them, and hands each to `serve` (none:
// only counted) with its blocking reads bounded by 5 s. A fake peer (a redirecting instance, a
// place a client must never reach) is written as `serve`.

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>

namespace carrom::test_support {

class TcpListener {
public:
    using Serve = std::function<void(boost::asio::ip::tcp::socket&)>;
    explicit TcpListener(const std::string& address = "127.0.0.1", Serve serve = {});
    ~TcpListener(); // stops accepting; waits for the connection being served
    TcpListener(const TcpListener&) = delete;
    TcpListener& operator=(const TcpListener&) = delete;

    std::uint16_t port() const { return port_; }
    int accepted() const { return accepted_; }

private:
    boost::asio::io_context ioc_;
    boost::asio::ip::tcp::acceptor acceptor_;
    std::uint16_t port_ = 0;
    std::atomic<bool> stopping_{false};
    std::atomic<int> accepted_{0};
    std::thread thread_;
};

} // namespace carrom::test_support
