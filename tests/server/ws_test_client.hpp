#pragma once
// A minimal WebSocket client for the socket tests: synchronous writes, reads with a deadline,
// decoded with proto. Beast stays in ws_test_client.cpp, compiled once for every socket test.

#include "carrom/proto/codec.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carrom::server::testing {

class WsTestClient {
public:
    // receive_buffer: SO_RCVBUF in bytes before connecting (a small one makes a slow reader
    // whose unread data the kernels hold little of); 0 keeps the system's default.
    explicit WsTestClient(std::uint16_t port, int receive_buffer = 0);
    ~WsTestClient();
    WsTestClient(const WsTestClient&) = delete;
    WsTestClient& operator=(const WsTestClient&) = delete;

    void send(const proto::ClientMessage& message) { send_text(proto::encode(message)); }
    void send_text(const std::string& text);
    // Sends a text frame; false when the server already cut the connection.
    bool try_send_text(const std::string& text);
    void send_binary(const std::string& bytes);

    // The next message, or nothing on timeout or when the connection closed.
    std::optional<proto::ServerMessage>
    read(std::chrono::milliseconds timeout = std::chrono::milliseconds(5000));

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
    int wait_for_close();
    // Closes the socket without a WebSocket close.
    void drop();

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
    struct Link; // the Beast stream and its io_context
    std::unique_ptr<Link> link_;
    bool closed_ = false;
    int close_code_ = 0;
};

} // namespace carrom::server::testing
