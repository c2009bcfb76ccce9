#include "server/ws_test_client.hpp"

#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

namespace carrom::server::testing {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;

struct WsTestClient::Link {
    asio::io_context ioc;
    websocket::stream<beast::tcp_stream> ws{ioc};

    // Ends a read that ran past its deadline. One cancel is not enough: when the deadline falls
    // between two steps of the read (its handler for a keep-alive ping queued, no socket
    // operation pending), the cancel finds nothing, and the read answers the ping and waits on
    // the socket again, for a message that may never come. So cancel until the read has ended;
    // close the socket only if that does not end it, since callers expect the connection to
    // stay open (the server still counts it).
    void end_read(const std::optional<beast::error_code>& result) {
        auto& socket = beast::get_lowest_layer(ws).socket();
        for (int attempt = 0; !result && attempt < 500; ++attempt) {
            socket.cancel();
            ioc.restart();
            ioc.run_for(std::chrono::milliseconds(10));
        }
        if (!result) {
            beast::error_code ignored;
            socket.close(ignored);
            ioc.restart();
            ioc.run();
        }
    }
};

WsTestClient::WsTestClient(std::uint16_t port, int receive_buffer)
    : link_(std::make_unique<Link>()) {
    auto& socket = beast::get_lowest_layer(link_->ws).socket();
    socket.open(asio::ip::tcp::v4());
    if (receive_buffer > 0) {
        socket.set_option(asio::socket_base::receive_buffer_size(receive_buffer));
    }
    socket.connect(asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    link_->ws.handshake("127.0.0.1", "/");
}

WsTestClient::~WsTestClient() = default;

void WsTestClient::send_text(const std::string& text) {
    link_->ws.text(true);
    link_->ws.write(asio::buffer(text));
}

bool WsTestClient::try_send_text(const std::string& text) {
    beast::error_code ec;
    link_->ws.text(true);
    link_->ws.write(asio::buffer(text), ec);
    return !ec;
}

void WsTestClient::send_binary(const std::string& bytes) {
    link_->ws.binary(true);
    link_->ws.write(asio::buffer(bytes));
}

std::optional<proto::ServerMessage> WsTestClient::read(std::chrono::milliseconds timeout) {
    if (closed_) {
        return std::nullopt;
    }
    beast::flat_buffer buffer;
    std::optional<beast::error_code> result;
    link_->ws.async_read(buffer, [&](beast::error_code ec, std::size_t) { result = ec; });
    link_->ioc.restart();
    link_->ioc.run_for(timeout);
    if (!result) {
        link_->end_read(result);
        closed_ = true; // a cancelled read leaves the stream unusable
        return std::nullopt;
    }
    if (*result) {
        closed_ = true;
        close_code_ = link_->ws.reason().code;
        return std::nullopt;
    }
    const std::string text = beast::buffers_to_string(buffer.data());
    auto decoded = proto::decode_server(text);
    if (!decoded.ok()) {
        ADD_FAILURE() << "undecodable server message: " << text;
        return std::nullopt;
    }
    log.push_back(*decoded.message);
    return decoded.message;
}

int WsTestClient::wait_for_close() {
    while (read()) {
    }
    return close_code_;
}

void WsTestClient::drop() {
    beast::error_code ignored;
    beast::get_lowest_layer(link_->ws).socket().close(ignored);
    closed_ = true;
}

} // namespace carrom::server::testing
