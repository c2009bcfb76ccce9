#include "carrom/net/http_get.hpp"

#include "carrom/tls/client_tls.hpp"
#include "quoted_url.hpp"
#include "ws_error_text.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/empty_body.hpp>
#include <boost/beast/http/parser.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/string_body.hpp>
#include <boost/beast/http/write.hpp>

#include <algorithm>
#include <cstdint>
#include <optional>

namespace carrom::net {

namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

std::string size_text(std::size_t bytes) {
    return bytes % (1U << 20U) == 0 ? std::to_string(bytes >> 20U) + " MiB"
                                    : std::to_string(bytes) + " bytes";
}

// One GET on its own io_context; the stream's deadline covers every step. tls_context: for an
// https:// url (null for http://). any_status: every status's answer comes back with its body.
class Exchange {
public:
    Exchange(WsUrl url, const HttpLimits& limits,
             std::shared_ptr<asio::ssl::context> tls_context = nullptr, bool any_status = false)
        : url_(std::move(url)), limits_(limits), tls_context_(std::move(tls_context)),
          any_status_(any_status), resolver_(ioc_), stream_(ioc_) {
        parser_.body_limit(static_cast<std::uint64_t>(limits_.max_body_bytes));
        parser_.header_limit(64U * 1024U);
    }

    std::variant<HttpResponse, std::string> run() {
        stream_.next_layer().expires_after(limits_.timeout);
        resolver_.async_resolve(url_.host, std::to_string(url_.port),
                                [this](beast::error_code ec, tcp::resolver::results_type found) {
                                    on_resolve(ec, std::move(found));
                                });
        ioc_.run_for(limits_.timeout + std::chrono::milliseconds(500));
        if (!result_) {
            return connect_timeout_text(url_, limits_.timeout);
        }
        return std::move(*result_);
    }

private:
    void fail(std::string text) { result_ = std::move(text); }

    void on_resolve(beast::error_code ec, const tcp::resolver::results_type& found) {
        if (ec) {
            return fail(resolve_error_text(url_, ec));
        }
        stream_.next_layer().async_connect(
            found, [this](beast::error_code e, const tcp::endpoint&) {
                if (e == beast::error::timeout) {
                    return fail(connect_timeout_text(url_, limits_.timeout));
                }
                if (e) {
                    return fail(connect_error_text(url_, e));
                }
                if (!tls_context_) {
                    return send();
                }
                if (!tls::start_client_tls(stream_, tls_context_, url_.host, verify_failure_)) {
                    return fail("The host name " + url_.host + " cannot be used for TLS.");
                }
                stream_.tls().async_handshake(asio::ssl::stream_base::client,
                                              [this](beast::error_code h) {
                                                  if (h) {
                                                      return fail(tls::tls_handshake_error_text(
                                                          url_.authority(), h, verify_failure_));
                                                  }
                                                  send();
                                              });
            });
    }

    void send() {
        request_.method(http::verb::get);
        request_.target(url_.target);
        request_.version(11);
        request_.set(http::field::host, url_.authority());
        request_.set(http::field::user_agent, "carrom-client");
        request_.set(http::field::accept, "application/json");
        http::async_write(stream_, request_, [this](beast::error_code ec, std::size_t) {
            if (ec) {
                return fail(lost_text(ec));
            }
            http::async_read_header(stream_, buffer_, parser_,
                                    [this](beast::error_code e, std::size_t) { on_header(e); });
        });
    }

    // The parser's own body limit is set too, but the body is also read piece by piece and
    // measured here, so that no answer (with a length, chunked, or until the end of the stream)
    // is held beyond the limit plus one read.
    bool over_limit() const {
        const auto length = parser_.content_length();
        return (length && *length > limits_.max_body_bytes) ||
               parser_.get().body().size() > limits_.max_body_bytes;
    }

    void too_large() {
        fail(url_.authority() + " sent more than " + size_text(limits_.max_body_bytes) + " for " +
             url_.target + ".");
    }

    void on_header(beast::error_code ec) {
        if (ec == http::error::body_limit) {
            return too_large();
        }
        if (ec) {
            return fail(lost_text(ec));
        }
        const auto& response = parser_.get();
        if (response.result_int() != 200 &&
            !any_status_) { // the body (an error page) is not needed
            return fail(url_.authority() + url_.target + " answered " +
                        std::to_string(response.result_int()) + " " +
                        std::string(response.reason().data(), response.reason().size()) + ".");
        }
        if (over_limit()) {
            return too_large();
        }
        read_body();
    }

    void read_body() {
        if (parser_.is_done()) {
            return done();
        }
        http::async_read_some(stream_, buffer_, parser_, [this](beast::error_code ec, std::size_t) {
            if (ec == http::error::body_limit || (!ec && over_limit())) {
                return too_large();
            }
            if (ec) {
                return fail(lost_text(ec));
            }
            read_body();
        });
    }

    void done() {
        result_ = HttpResponse{parser_.get().result_int(), std::move(parser_.get().body())};
        beast::error_code ignored;
        stream_.next_layer().socket().shutdown(tcp::socket::shutdown_both, ignored);
    }

    std::string lost_text(beast::error_code ec) const {
        if (ec == beast::error::timeout) {
            return url_.authority() + " did not answer within " +
                   std::to_string(limits_.timeout.count()) + " ms.";
        }
        return url_.authority() + " broke off the answer (" + ec.message() + ").";
    }

    WsUrl url_;
    HttpLimits limits_;
    std::shared_ptr<asio::ssl::context> tls_context_;
    bool any_status_ = false;
    asio::io_context ioc_;
    tcp::resolver resolver_;
    tls::FlexStream<beast::tcp_stream> stream_;
    tls::VerifyFailure verify_failure_; // the certificate refused in the TLS handshake
    http::request<http::empty_body> request_;
    beast::flat_buffer buffer_;
    http::response_parser<http::string_body> parser_;
    std::optional<std::variant<HttpResponse, std::string>> result_;
};

} // namespace

namespace {

// http://... (and with allow_https, https://...) as host, port (80 or 443 by default), target
// and whether it is TLS; or one sentence.
std::variant<WsUrl, std::string> parse_url(std::string_view url, bool allow_https) {
    const bool https = allow_https && url.substr(0, 8) == "https://";
    const std::string_view kScheme = https ? "https://" : "http://";
    if (!https && url.substr(0, 8) == "https://") {
        return "The address " + quoted_url(url) +
               " uses https, which is not supported: use http://.";
    }
    if (url.substr(0, kScheme.size()) != kScheme) {
        return "The address " + quoted_url(url) + " must start with http://" +
               (allow_https ? " or https://." : ".");
    }
    const std::string_view rest = url.substr(kScheme.size());
    const std::string_view authority = rest.substr(0, rest.find_first_of("/?#"));
    // "[::1]:8080", "[::1]", "host:8080", "host": a port follows the last ':' after any ']'.
    const auto bracket = authority.rfind(']');
    const auto colon = authority.rfind(':');
    const bool has_port =
        colon != std::string_view::npos && (bracket == std::string_view::npos || colon > bracket);
    const std::string as_ws = (https ? "wss://" : "ws://") + std::string(authority) +
                              (has_port ? ""
                               : https  ? ":443"
                                        : ":80") +
                              std::string(rest.substr(authority.size()));
    auto parsed = parse_ws_url(as_ws);
    if (std::holds_alternative<std::string>(parsed)) {
        return "The address " + quoted_url(url) + " is not " + std::string(kScheme) +
               "HOST[:PORT]/PATH with a host and a port from 1 to 65535.";
    }
    return parsed;
}

} // namespace

std::variant<WsUrl, std::string> parse_http_url(std::string_view url) {
    return parse_url(url, false);
}

std::variant<HttpResponse, std::string> http_get(std::string_view url, const HttpLimits& limits) {
    auto parsed = parse_http_url(url);
    if (auto* problem = std::get_if<std::string>(&parsed)) {
        return std::move(*problem);
    }
    Exchange exchange(std::get<WsUrl>(std::move(parsed)), limits);
    return exchange.run();
}

std::variant<HttpResponse, std::string>
http_get_any_status(std::string_view url, const HttpLimits& limits, const std::string& ca_file) {
    auto parsed = parse_url(url, true);
    if (auto* problem = std::get_if<std::string>(&parsed)) {
        return std::move(*problem);
    }
    WsUrl target = std::get<WsUrl>(std::move(parsed));
    std::shared_ptr<asio::ssl::context> tls_context;
    if (target.tls) {
        auto made = tls::client_tls_context(ca_file);
        if (auto* problem = std::get_if<std::string>(&made)) {
            return std::move(*problem);
        }
        tls_context = std::get<0>(std::move(made));
    }
    Exchange exchange(std::move(target), limits, std::move(tls_context), true);
    return exchange.run();
}

} // namespace carrom::net
