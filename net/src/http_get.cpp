#include "carrom/net/http_get.hpp"

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

// One GET on its own io_context; the stream's deadline covers every step.
class Exchange {
public:
    Exchange(WsUrl url, const HttpLimits& limits)
        : url_(std::move(url)), limits_(limits), resolver_(ioc_), stream_(ioc_) {
        parser_.body_limit(static_cast<std::uint64_t>(limits_.max_body_bytes));
        parser_.header_limit(64U * 1024U);
    }

    std::variant<HttpResponse, std::string> run() {
        stream_.expires_after(limits_.timeout);
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
        stream_.async_connect(found, [this](beast::error_code e, const tcp::endpoint&) {
            if (e == beast::error::timeout) {
                return fail(connect_timeout_text(url_, limits_.timeout));
            }
            if (e) {
                return fail(connect_error_text(url_, e));
            }
            send();
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
        if (response.result_int() != 200) { // the body (an error page) is not needed
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
        stream_.socket().shutdown(tcp::socket::shutdown_both, ignored);
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
    asio::io_context ioc_;
    tcp::resolver resolver_;
    beast::tcp_stream stream_;
    http::request<http::empty_body> request_;
    beast::flat_buffer buffer_;
    http::response_parser<http::string_body> parser_;
    std::optional<std::variant<HttpResponse, std::string>> result_;
};

} // namespace

std::variant<WsUrl, std::string> parse_http_url(std::string_view url) {
    constexpr std::string_view kScheme = "http://";
    if (url.substr(0, 8) == "https://") {
        return "The address " + quoted_url(url) +
               " uses https, which is not supported: use http://.";
    }
    if (url.substr(0, kScheme.size()) != kScheme) {
        return "The address " + quoted_url(url) + " must start with http://.";
    }
    const std::string_view rest = url.substr(kScheme.size());
    const std::string_view authority = rest.substr(0, rest.find_first_of("/?#"));
    // "[::1]:8080", "[::1]", "host:8080", "host": a port follows the last ':' after any ']'.
    const auto bracket = authority.rfind(']');
    const auto colon = authority.rfind(':');
    const bool has_port =
        colon != std::string_view::npos && (bracket == std::string_view::npos || colon > bracket);
    const std::string as_ws = "ws://" + std::string(authority) + (has_port ? "" : ":80") +
                              std::string(rest.substr(authority.size()));
    auto parsed = parse_ws_url(as_ws);
    if (std::holds_alternative<std::string>(parsed)) {
        return "The address " + quoted_url(url) +
               " is not http://HOST[:PORT]/PATH with a host and a port from 1 to 65535.";
    }
    return parsed;
}

std::variant<HttpResponse, std::string> http_get(std::string_view url, const HttpLimits& limits) {
    auto parsed = parse_http_url(url);
    if (auto* problem = std::get_if<std::string>(&parsed)) {
        return std::move(*problem);
    }
    Exchange exchange(std::get<WsUrl>(std::move(parsed)), limits);
    return exchange.run();
}

} // namespace carrom::net
