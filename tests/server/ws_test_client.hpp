#pragma once
// A minimal Beast WebSocket client for the socket tests: synchronous writes, reads with a
// deadline (run_for on a private io_context), decoded with proto.

#include "carrom/proto/codec.hpp"

#include <gtest/gtest.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace carrom::server::testing {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;

class WsTestClient {
public:
    // receive_buffer: SO_RCVBUF in bytes before connecting (a small one makes a slow reader
    // whose unread data the kernels hold little of); 0 keeps the system's default.
    explicit WsTestClient(std::uint16_t port, int receive_buffer = 0) : ws_(ioc_) {
        auto& socket = beast::get_lowest_layer(ws_).socket();
        socket.open(asio::ip::tcp::v4());
        if (receive_buffer > 0) {
            socket.set_option(asio::socket_base::receive_buffer_size(receive_buffer));
        }
        socket.connect(asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
        ws_.handshake("127.0.0.1", "/");
    }

    void send(const proto::ClientMessage& message) { send_text(proto::encode(message)); }
    void send_text(const std::string& text) {
        ws_.text(true);
        ws_.write(asio::buffer(text));
    }
    // Sends a text frame; false when the server already cut the connection.
    bool try_send_text(const std::string& text) {
        beast::error_code ec;
        ws_.text(true);
        ws_.write(asio::buffer(text), ec);
        return !ec;
    }
    void send_binary(const std::string& bytes) {
        ws_.binary(true);
        ws_.write(asio::buffer(bytes));
    }

    // The next message, or nothing on timeout or when the connection closed (see closed()).
    std::optional<proto::ServerMessage>
    read(std::chrono::milliseconds timeout = std::chrono::milliseconds(5000)) {
        if (closed_) {
            return std::nullopt;
        }
        beast::flat_buffer buffer;
        std::optional<beast::error_code> result;
        ws_.async_read(buffer, [&](beast::error_code ec, std::size_t) { result = ec; });
        ioc_.restart();
        ioc_.run_for(timeout);
        if (!result) {
            end_read(result);
            closed_ = true; // a cancelled read leaves the stream unusable
            return std::nullopt;
        }
        if (*result) {
            closed_ = true;
            close_code_ = ws_.reason().code;
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

    // Reads until a message of type T arrives (everything read is kept in `log`).
    template <class T>
    std::optional<T> wait_for(std::chrono::milliseconds timeout = std::chrono::milliseconds(5000)) {
        const auto deadline = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < deadline) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            auto message = read(std::max(left, std::chrono::milliseconds(1)));
            if (!message) {
                return std::nullopt;
            }
            if (auto* t = std::get_if<T>(&*message)) {
                return *t;
            }
        }
        return std::nullopt;
    }
    template <class T> std::optional<T> wait_for_event() {
        for (;;) {
            auto event = wait_for<proto::Event>();
            if (!event) {
                return std::nullopt;
            }
            if (auto* t = std::get_if<T>(&*event)) {
                return *t;
            }
        }
    }
    std::string wait_for_error() {
        auto error = wait_for<proto::Error>();
        return error ? error->code : std::string("<none>");
    }
    // Reads until the server closes; returns its close code.
    int wait_for_close() {
        while (read()) {
        }
        return close_code_;
    }
    void drop() {
        beast::error_code ignored;
        beast::get_lowest_layer(ws_).socket().close(ignored);
        closed_ = true;
    }

    template <class T> std::vector<T> logged() const {
        std::vector<T> out;
        for (const auto& m : log) {
            if (const auto* t = std::get_if<T>(&m)) {
                out.push_back(*t);
            }
        }
        return out;
    }

    std::vector<proto::ServerMessage> log;

private:
    // Ends a read that ran past its deadline. One cancel is not enough: when the deadline falls
    // between two steps of the read (its handler for a keep-alive ping queued, no socket
    // operation pending), the cancel finds nothing, and the read answers the ping and waits on
    // the socket again, for a message that may never come. So cancel until the read has ended;
    // close the socket only if that does not end it, since callers expect the connection to
    // stay open (the server still counts it).
    void end_read(const std::optional<beast::error_code>& result) {
        auto& socket = beast::get_lowest_layer(ws_).socket();
        for (int attempt = 0; !result && attempt < 500; ++attempt) {
            socket.cancel();
            ioc_.restart();
            ioc_.run_for(std::chrono::milliseconds(10));
        }
        if (!result) {
            beast::error_code ignored;
            socket.close(ignored);
            ioc_.restart();
            ioc_.run();
        }
    }

    asio::io_context ioc_;
    websocket::stream<beast::tcp_stream> ws_;
    bool closed_ = false;
    int close_code_ = 0;
};

} // namespace carrom::server::testing
