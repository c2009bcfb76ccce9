#pragma once
// Private to server/src: one plain HTTP connection. Reads a request; hands a WebSocket upgrade
// (any target) to a new WsSession; answers GET /healthz and GET /metrics (405 for another
// method); answers every other target from the web client's StaticSite when the server has one
// (404 when it has none). A request that cannot be read gets its status (400, 413, 414, 431).
// A 200 or 304 of the site keeps the connection open for the next request when the client asks
// for it; every other answer closes it (lingering: the rest of the request is read and dropped
// for a moment, so the client reads the answer before the connection ends).

#include "asio_types.hpp"

#include <boost/beast/core/flat_buffer.hpp>

#include <array>
#include <memory>
#include <optional>

namespace carrom::server {

struct ServerCore;

class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
    HttpSession(ServerCore& core, tcp::socket socket);

    void run();

private:
    using Request = http::request<http::string_body>;
    using Response = http::response<http::string_body>;

    void read_request();
    void on_read(beast::error_code ec, std::size_t bytes);
    void respond(const Request& request);
    void respond_web(const Request& request);
    // The status for a request that could not be read, or nothing (closed, timed out).
    std::optional<http::status> read_error_status(beast::error_code ec) const;
    void refuse(http::status status);
    void write(std::shared_ptr<Response> response, bool keep_alive);
    void close();
    void drain();

    ServerCore& core_;
    beast::tcp_stream stream_;
    beast::flat_buffer buffer_;
    std::optional<http::request_parser<http::string_body>> parser_;
    std::array<char, 1024> drained_{};
};

} // namespace carrom::server
