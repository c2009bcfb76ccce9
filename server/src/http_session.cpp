#include "http_session.hpp"

#include "client_address.hpp"

#include "match_api.hpp"
#include "server_core.hpp"
#include "tls_context.hpp"
#include "ws_session.hpp"

#include <boost/asio/buffer.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core/bind_handler.hpp>
#include <boost/beast/websocket/rfc6455.hpp>

#include <cstdio>
#include <string>
#include <string_view>

namespace carrom::server {
namespace {

// The request line and headers together; a longer request line is 414, longer headers 431.
constexpr std::uint32_t kHeaderLimit = 8192;
// No endpoint takes a body; a larger one is 413.
constexpr std::uint64_t kBodyLimit = 1024;
// How long a closing connection reads and drops what the client still sends.
constexpr std::chrono::seconds kLinger{2};

std::string_view refusal_sentence(http::status status) {
    switch (status) {
    case http::status::payload_too_large:
        return "Request body too large.\n";
    case http::status::uri_too_long:
        return "URI too long.\n";
    case http::status::request_header_fields_too_large:
        return "Request header fields too large.\n";
    default:
        return "Bad request: it is not a well-formed HTTP/1.1 request.\n";
    }
}

} // namespace

HttpSession::HttpSession(ServerCore& core, ServerStream stream, beast::flat_buffer buffer)
    : core_(core), stream_(std::move(stream)), buffer_(std::move(buffer)),
      deadline_(stream_.get_executor()) {}

void HttpSession::run() {
    read_request();
}

void HttpSession::read_request() {
    parser_.emplace();
    parser_->header_limit(kHeaderLimit);
    parser_->body_limit(kBodyLimit);
    expire_after(to_duration(core_.settings.handshake_timeout_s));
    http::async_read(stream_, buffer_, *parser_,
                     beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
}

std::optional<http::status> HttpSession::read_error_status(beast::error_code ec) const {
    if (ec.category() != http::make_error_code(http::error::bad_target).category() ||
        ec == http::error::end_of_stream || ec == http::error::partial_message) {
        return std::nullopt; // timeout, reset, or the client closed
    }
    if (ec == http::error::body_limit) {
        return http::status::payload_too_large;
    }
    if (ec == http::error::header_limit) {
        // No target yet: the request line itself did not end within the limit.
        return parser_->get().target().empty() ? http::status::uri_too_long
                                               : http::status::request_header_fields_too_large;
    }
    return http::status::bad_request;
}

void HttpSession::on_read(beast::error_code ec, std::size_t) {
    if (ec) {
        if (const auto status = read_error_status(ec)) {
            core_.metrics.http_requests_total.fetch_add(1, std::memory_order_relaxed);
            refuse(*status);
        }
        return;
    }
    auto request = parser_->release();
    if (beast::websocket::is_upgrade(request)) {
        deadline_.cancel(); // the WebSocket handshake has its own
        std::make_shared<WsSession>(core_, std::move(stream_))->run(std::move(request));
        return;
    }
    core_.metrics.http_requests_total.fetch_add(1, std::memory_order_relaxed);
    respond(request);
}

void HttpSession::respond(const Request& request) {
    const auto target = request.target();
    const std::string_view target_view(target.data(), target.size());
    const bool api = is_match_api_target(target_view);
    if (target != "/healthz" && target != "/metrics" && !api && core_.web) {
        respond_web(request);
        return;
    }
    const bool head = request.method() == http::verb::head;
    if ((api || target == "/metrics") &&
        refuse_over_rate(request.version(), head, std::string(request["X-Forwarded-For"]))) {
        return;
    }
    auto response = std::make_shared<Response>();
    response->version(request.version());
    response->set(http::field::server, "carrom-server");
    const bool get = request.method() == http::verb::get;
    if (target == "/healthz" || target == "/metrics" || api) {
        if (!get) {
            response->result(http::status::method_not_allowed);
            response->set(http::field::allow, "GET");
            response->body() = "method not allowed\n";
        } else if (api) {
            answer_api(request.version(), target_view);
            return;
        } else if (target == "/healthz") {
            // 200 "ok"; 200 "degraded: " and why, "; " between reasons: "cluster lease not
            // renewed" (cluster mode, the last lease round failed), "match store not writing (N
            // waiting): LAST ERROR" (its writes fail: strokes wait, new matches are refused);
            // 503 "stopping" during shutdown; in cluster mode a line "cluster: {...}"; with TLS,
            // a line "tls: {...}".
            std::optional<store::StoreHealth> health;
            if (core_.store) {
                health = core_.store->health();
            }
            std::optional<store::ClusterStatus> cluster;
            if (core_.store && core_.store->cluster() != nullptr) {
                cluster = core_.store->cluster()->status();
            }
            response->result(core_.stopping ? http::status::service_unavailable : http::status::ok);
            if (core_.stopping) {
                response->body() = "stopping\n";
            } else if ((health && health->degraded) || (cluster && !cluster->lease_ok)) {
                std::string reasons =
                    cluster && !cluster->lease_ok ? "cluster lease not renewed" : "";
                if (health && health->degraded) {
                    reasons += (reasons.empty() ? "" : "; ") +
                               std::string("match store not writing (") +
                               std::to_string(health->pending) + " waiting): " + health->last_error;
                }
                response->body() = "degraded: " + reasons + "\n";
            } else {
                response->body() = "ok\n";
            }
            if (health) { // which backend (sqlite, postgresql), for operators and probes
                response->set("Carrom-Store", health->backend);
            }
            if (cluster && !core_.stopping) {
                response->body() += cluster_health_line(*cluster);
            }
            if (core_.tls && !core_.stopping) { // the certificate in use, the last reload
                response->body() += "tls: " + core_.tls->health_json() + "\n";
            }
        } else {
            response->result(http::status::ok);
            response->set(http::field::content_type, "text/plain; version=0.0.4");
            std::optional<store::StoreHealth> health;
            if (core_.store) {
                health = core_.store->health();
            }
            response->body() = core_.metrics.prometheus_text() +
                               store_prometheus_text(health ? &*health : nullptr);
            if (core_.store && core_.store->cluster() != nullptr) {
                response->body() += cluster_prometheus_text(core_.store->cluster()->status());
            }
        }
    } else {
        response->result(http::status::not_found);
        response->body() = "not found\n";
    }
    send(std::move(response), head);
}

bool HttpSession::refuse_over_rate(unsigned version, bool head, std::string_view forwarded_for) {
    beast::error_code ec;
    const auto remote = stream_.next_layer().remote_endpoint(ec);
    const std::string address = client_address(ec ? std::string() : remote.address().to_string(),
                                               forwarded_for, core_.settings.trusted_proxies);
    const int retry_s = core_.http_limiter.take(address, core_.clock.now_ms());
    if (retry_s == 0) {
        return false;
    }
    core_.metrics.http_rate_limited_total.fetch_add(1, std::memory_order_relaxed);
    char limits[96];
    std::snprintf(limits, sizeof limits, "%g requests per second, bursts of %g",
                  core_.settings.http_rate, core_.settings.http_burst);
    auto response =
        api_response(version, match_api_error(429, match_api_code::kRateLimited,
                                              "Too many requests from your address (at most " +
                                                  std::string(limits) + "); retry in " +
                                                  std::to_string(retry_s) + " s."));
    response->set(http::field::retry_after, std::to_string(retry_s));
    send(std::move(response), head);
    return true;
}

void HttpSession::answer_api(unsigned version, std::string_view target) {
    if (!core_.match_reader) { // no store: nothing to read
        send(api_response(version, answer_match_api(nullptr, target)), false);
        return;
    }
    deadline_.cancel(); // the read may take longer; the write gets a fresh deadline
    const bool queued = core_.match_reader->submit(
        std::string(target), [self = shared_from_this(), executor = stream_.get_executor(),
                              version](MatchApiAnswer answer) {
            asio::post(executor, [self, version, answer = std::move(answer)] {
                self->expire_after(to_duration(self->core_.settings.handshake_timeout_s));
                self->send(self->api_response(version, answer), false);
            });
        });
    if (!queued) {
        send(api_response(version, match_api_error(503, match_api_code::kStoreBusy,
                                                   "Too many match store reads wait; retry "
                                                   "in a moment.")),
             false);
    }
}

std::shared_ptr<HttpSession::Response> HttpSession::api_response(unsigned version,
                                                                 const MatchApiAnswer& answer) {
    auto response = std::make_shared<Response>();
    response->version(version);
    response->set(http::field::server, "carrom-server");
    response->result(static_cast<unsigned>(answer.status));
    response->set(http::field::content_type, "application/json");
    response->set(http::field::cache_control, "no-store");
    response->body() = answer.body;
    return response;
}

void HttpSession::send(std::shared_ptr<Response> response, bool head) {
    if (response->body().size() > 0 &&
        response->find(http::field::content_type) == response->end()) {
        response->set(http::field::content_type, "text/plain");
    }
    response->prepare_payload();
    if (head) {
        response->body().clear(); // the GET's Content-Length, no body
    }
    write(std::move(response), false);
}

void HttpSession::respond_web(const Request& request) {
    const auto view = [](beast::string_view v) { return std::string_view(v.data(), v.size()); };
    StaticRequest asked{view(request.method_string()), view(request.target()), std::nullopt};
    if (const auto it = request.find(http::field::if_none_match); it != request.end()) {
        asked.if_none_match = view(it->value());
    }
    const StaticResponse answer = core_.web->respond(asked);
    auto response = std::make_shared<Response>();
    response->version(request.version());
    response->result(static_cast<unsigned>(answer.status));
    response->set(http::field::server, "carrom-server");
    for (const HttpHeader& h : answer.headers) {
        response->set(h.name, h.value); // Content-Length included (a HEAD's is the GET's)
    }
    response->body().assign(answer.body);
    const bool served = answer.status == 200 || answer.status == 304;
    write(std::move(response), served && request.keep_alive());
}

void HttpSession::refuse(http::status status) {
    const std::string_view sentence = refusal_sentence(status);
    auto response = std::make_shared<Response>(status, 11);
    response->set(http::field::server, "carrom-server");
    response->set(http::field::content_type, "text/plain; charset=utf-8");
    response->set(http::field::cache_control, "no-store");
    response->body().assign(sentence);
    response->prepare_payload();
    write(std::move(response), false);
}

void HttpSession::write(std::shared_ptr<Response> response, bool keep_alive) {
    response->keep_alive(keep_alive);
    http::async_write(
        stream_, *response,
        [self = shared_from_this(), response, keep_alive](beast::error_code ec, std::size_t) {
            if (ec) {
                return;
            }
            if (keep_alive) {
                self->read_request();
            } else {
                self->close();
            }
        });
}

void HttpSession::close() {
    expire_after(kLinger);
    if (stream_.is_tls()) { // close_notify; the client's answer to it ends the connection
        stream_.tls().async_shutdown([self = shared_from_this()](beast::error_code) {
            beast::error_code ignored;
            self->stream_.next_layer().close(ignored);
        });
        return;
    }
    beast::error_code ignored;
    stream_.next_layer().shutdown(tcp::socket::shutdown_send, ignored);
    drain();
}

void HttpSession::expire_after(std::chrono::milliseconds timeout) {
    deadline_.expires_after(timeout);
    deadline_.async_wait([weak = weak_from_this()](beast::error_code ec) {
        if (ec) {
            return; // re-armed, cancelled or the session ended
        }
        if (auto self = weak.lock()) {
            beast::error_code ignored;
            self->stream_.next_layer().close(ignored);
        }
    });
}

void HttpSession::drain() {
    stream_.async_read_some(asio::buffer(drained_),
                            [self = shared_from_this()](beast::error_code ec, std::size_t) {
                                if (!ec) {
                                    self->drain();
                                }
                            });
}

} // namespace carrom::server
