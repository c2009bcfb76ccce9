#include "ws_error_text.hpp"

#include <boost/asio/error.hpp>
#include <boost/beast/core/error.hpp>
#include <boost/beast/websocket/error.hpp>

#include <cctype>

namespace carrom::net {

namespace {

// "5 s" for whole seconds, "1500 ms" otherwise.
std::string duration_text(std::chrono::milliseconds duration) {
    const auto ms = duration.count();
    return ms % 1000 == 0 ? std::to_string(ms / 1000) + " s" : std::to_string(ms) + " ms";
}

namespace asio_error = boost::asio::error;
namespace websocket = boost::beast::websocket;

std::string lower_first(std::string text) {
    if (!text.empty()) {
        text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    }
    return text;
}

// The system's wording without a trailing period.
std::string plain(const boost::system::error_code& ec) {
    std::string text = lower_first(ec.message());
    while (!text.empty() && (text.back() == '.' || text.back() == ' ')) {
        text.pop_back();
    }
    return text;
}

} // namespace

std::string resolve_error_text(const WsUrl& url, const boost::system::error_code& ec) {
    if (ec == asio_error::host_not_found || ec == asio_error::host_not_found_try_again) {
        return "Could not find the server host '" + url.host + "' (no such host name).";
    }
    return "Could not find the server host '" + url.host + "' (" + plain(ec) + ").";
}

std::string connect_error_text(const WsUrl& url, const boost::system::error_code& ec) {
    const std::string head = "Could not reach " + url.authority() + ": ";
    if (ec == asio_error::connection_refused) {
        return head + "connection refused.";
    }
    if (ec == asio_error::network_unreachable) {
        return head + "the network is unreachable.";
    }
    if (ec == asio_error::host_unreachable) {
        return head + "the host is unreachable.";
    }
    if (ec == asio_error::timed_out) {
        return head + "no answer.";
    }
    return head + plain(ec) + ".";
}

std::string connect_timeout_text(const WsUrl& url, std::chrono::milliseconds timeout) {
    return "Could not reach " + url.authority() + ": no answer within " + duration_text(timeout) +
           ".";
}

std::string silence_text(const WsUrl& url, std::chrono::milliseconds timeout) {
    return "Nothing arrived from " + url.authority() + " for " + duration_text(timeout) +
           ": the link is silent, taken for lost.";
}

std::string handshake_error_text(const WsUrl& url, const boost::system::error_code& ec) {
    if (ec == boost::beast::error::timeout) {
        return "Could not reach " + url.authority() + ": no WebSocket answer in time.";
    }
    return url.authority() + " answered, but not as a WebSocket server (" + plain(ec) + ").";
}

std::string close_code_meaning(std::uint16_t close_code) {
    switch (close_code) {
    case 1000:
        return "normal close";
    case 1001:
        return "the server is shutting down";
    case 1003:
        return "it accepts text frames only";
    case 1008:
        return "a server limit or timeout was hit";
    case 1009:
        return "a message was too large";
    case 1011:
        return "the server had an internal error";
    case 1012:
        return "the server is restarting";
    case 1013:
        return "the server is full, try again later";
    case 4001:
        return "this client speaks another protocol version";
    case 4002:
        return "the seat was resumed on another connection";
    case 4003:
        return "this client read too slowly";
    case 4004:
        return "the match moved to another server instance";
    default:
        return "close code " + std::to_string(close_code);
    }
}

std::string read_error_text(const WsUrl& url, const boost::system::error_code& ec,
                            std::uint16_t close_code, const std::string& close_reason) {
    if (ec == websocket::error::closed) {
        std::string text = "The server closed the connection (code " + std::to_string(close_code) +
                           ": " + close_code_meaning(close_code);
        if (!close_reason.empty()) {
            text += "; it said '" + close_reason + "'";
        }
        return text + ").";
    }
    if (ec == boost::beast::websocket::error::message_too_big) {
        return "The connection to " + url.authority() +
               " was dropped: the server sent a message over the size limit.";
    }
    return "The connection to " + url.authority() + " was lost (" + plain(ec) + ").";
}

} // namespace carrom::net
