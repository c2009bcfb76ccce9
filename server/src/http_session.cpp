#include "http_session.hpp"

#include "server_core.hpp"
#include "ws_session.hpp"

#include <boost/beast/core/bind_handler.hpp>
#include <boost/beast/websocket/rfc6455.hpp>

namespace carrom::server {

HttpSession::HttpSession(ServerCore& core, tcp::socket socket)
    : core_(core), stream_(std::move(socket)) {}

void HttpSession::run() {
    parser_.emplace();
    parser_->header_limit(8192);
    parser_->body_limit(1024);
    stream_.expires_after(to_duration(core_.settings.handshake_timeout_s));
    http::async_read(stream_, buffer_, *parser_,
                     beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
    if (ec) {
        return; // timeout, garbage or a closed connection
    }
    auto request = parser_->release();
    if (beast::websocket::is_upgrade(request)) {
        std::make_shared<WsSession>(core_, std::move(stream_))->run(std::move(request));
        return;
    }
    core_.metrics.http_requests_total.fetch_add(1, std::memory_order_relaxed);
    respond(request);
}

void HttpSession::respond(const http::request<http::string_body>& request) {
    auto response = std::make_shared<http::response<http::string_body>>();
    response->version(request.version());
    response->set(http::field::server, "carrom-server");
    response->keep_alive(false);
    const auto target = request.target();
    const bool get = request.method() == http::verb::get;
    if (target == "/healthz" || target == "/metrics") {
        if (!get) {
            response->result(http::status::method_not_allowed);
            response->set(http::field::allow, "GET");
            response->body() = "method not allowed\n";
        } else if (target == "/healthz") {
            response->result(core_.stopping ? http::status::service_unavailable : http::status::ok);
            response->body() = core_.stopping ? "stopping\n" : "ok\n";
        } else {
            response->result(http::status::ok);
            response->set(http::field::content_type, "text/plain; version=0.0.4");
            response->body() = core_.metrics.prometheus_text();
        }
    } else {
        response->result(http::status::not_found);
        response->body() = "not found\n";
    }
    if (!response->has_content_length() && response->body().size() > 0 &&
        response->find(http::field::content_type) == response->end()) {
        response->set(http::field::content_type, "text/plain");
    }
    response->prepare_payload();
    http::async_write(stream_, *response,
                      [self = shared_from_this(), response](beast::error_code, std::size_t) {
                          beast::error_code ignored;
                          self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                      });
}

} // namespace carrom::server
