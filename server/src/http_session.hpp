#pragma once
// Private to server/src: one HTTP connection, plain or over TLS. Reads a request; hands a WebSocket
// upgrade (any target) to a new WsSession; answers GET /healthz, GET /metrics and the match API
// (405 for another method); answers every other target from the web client's StaticSite when the
// server has one (404 when it has none). A request that cannot be read gets its status (400, 413,
// 414, 431). The match API's reads run on the MatchApiReader's thread (match_api_reader.hpp), never
// here; the match API and /metrics are limited per client address (429 rate_limited).
// A 200 or 304 of the site keeps the connection open for the next request when the client asks
// for it; every other answer closes it (lingering: the rest of the request is read and dropped
// for a moment, so the client reads the answer before the connection ends).

#include "match_api.hpp"
#include "server_stream.hpp"

#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string_view>

namespace carrom::server {

struct ServerCore;

class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
    // buffer: bytes of the first request read already (TLS detection).
    HttpSession(ServerCore& core, ServerStream stream, beast::flat_buffer buffer = {});

    void run();

private:
    using Request = http::request<http::string_body>;
    using Response = http::response<http::string_body>;

    void read_request();
    void on_read(beast::error_code ec, std::size_t bytes);
    void respond(const Request& request);
    void respond_web(const Request& request);
    // The match API and /metrics: 429 rate_limited (true) when the client's address is over
    // settings.http_rate; false when the request may go on.
    bool refuse_over_rate(unsigned version, bool head, std::string_view forwarded_for);
    // A GET of the match API: read on core_.match_reader's thread, answered back on this
    // session's executor (503 store_busy when too many reads wait).
    void answer_api(unsigned version, std::string_view target);
    std::shared_ptr<Response> api_response(unsigned version, const MatchApiAnswer& answer);
    // Completes (default Content-Type, Content-Length; no body for a HEAD) and writes a
    // response that closes the connection.
    void send(std::shared_ptr<Response> response, bool head);
    // The status for a request that could not be read, or nothing (closed, timed out).
    std::optional<http::status> read_error_status(beast::error_code ec) const;
    void refuse(http::status status);
    void write(std::shared_ptr<Response> response, bool keep_alive);
    void close();
    void drain();
    // The socket is closed when the deadline passes (pending operations end with an error).
    void expire_after(std::chrono::milliseconds timeout);

    ServerCore& core_;
    ServerStream stream_;
    beast::flat_buffer buffer_;
    asio::steady_timer deadline_;
    std::optional<http::request_parser<http::string_body>> parser_;
    std::array<char, 1024> drained_{};
};

} // namespace carrom::server
