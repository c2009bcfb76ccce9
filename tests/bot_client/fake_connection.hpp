#pragma once
// A net::Connection for the runner's tests: records what the runner sends and delivers what the
// test queues (tests/bot_client/).

#include "carrom/net/connection.hpp"

#include <deque>
#include <functional>
#include <utility>
#include <vector>

namespace carrom::bots::fake {

// Records what the runner sends; delivers what the test queues.
struct FakeWire {
    std::vector<proto::ClientMessage> sent;
    std::deque<proto::ServerMessage> inbox;
    net::ConnectionStatus status{net::ConnectionState::Open, "fake"};
    int opened = 0;
    bool refuse = false; // connections opened from now on are refused
    // Runs once, just after the next poll: what the I/O thread receives between a poll and
    // whatever the runner asks next.
    std::function<void()> after_poll;
};

class FakeConnection final : public net::Connection {
public:
    explicit FakeConnection(FakeWire& wire) : wire_(wire) {}
    void send(const proto::ClientMessage& message) override { wire_.sent.push_back(message); }
    void send_text(const std::string&) override {}
    std::vector<proto::ServerMessage> poll() override {
        std::vector<proto::ServerMessage> out(wire_.inbox.begin(), wire_.inbox.end());
        wire_.inbox.clear();
        if (auto late = std::exchange(wire_.after_poll, nullptr)) {
            late();
        }
        return out;
    }
    bool wait(std::chrono::milliseconds) override { return !wire_.inbox.empty(); }
    net::ConnectionStatus status() const override { return wire_.status; }
    int decode_errors() const override { return 0; }
    void close() override { wire_.status = {net::ConnectionState::Closed, "closed"}; }

private:
    FakeWire& wire_;
};

} // namespace carrom::bots::fake
