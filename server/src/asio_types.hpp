#pragma once
// Private to server/src: the Boost.Asio and Boost.Beast names the network classes share, and
// settings in seconds as Asio durations. Only the network layer's .cpp files include it (through
// the private headers next to it); nothing under server/include does.

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>

namespace carrom::server {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

// A setting in seconds as whole milliseconds (rounded).
inline std::chrono::milliseconds to_duration(double seconds) {
    return std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(seconds * 1000.0)));
}

} // namespace carrom::server
