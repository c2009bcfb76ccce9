#pragma once
// Private to server/src: one plain HTTP connection. Reads one request; answers GET /healthz and
// GET /metrics, hands a WebSocket upgrade to a new WsSession, and answers anything else with 404
// (or 405 for another method on a known path). Closes after the answer.

#include "asio_types.hpp"

#include <boost/beast/core/flat_buffer.hpp>

#include <memory>
#include <optional>

namespace carrom::server {

struct ServerCore;

class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
    HttpSession(ServerCore& core, tcp::socket socket);

    void run();

private:
    void on_read(beast::error_code ec, std::size_t bytes);
    void respond(const http::request<http::string_body>& request);

    ServerCore& core_;
    beast::tcp_stream stream_;
    beast::flat_buffer buffer_;
    std::optional<http::request_parser<http::string_body>> parser_;
};

} // namespace carrom::server
