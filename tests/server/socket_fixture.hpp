#pragma once
// The socket tests' fixture: the real server on 127.0.0.1 with an ephemeral port, and helpers
// that connect clients, seat two players and ask over plain HTTP. No Boost here: the socket
// tests compile Beast once, in ws_test_client.cpp and socket_fixture.cpp.

#include "carrom/server/server.hpp"

#include "server/ws_test_client.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <numbers>
#include <optional>
#include <string>

namespace carrom::server::testing {

inline constexpr double kUp = -std::numbers::pi / 2.0;

inline ServerSettings test_settings() {
    ServerSettings s;
    s.host = "127.0.0.1";
    s.port = 0;
    s.threads = 2;
    s.shot_clock_s = 0.0;
    s.max_rate = 50.0;
    s.rate_burst = 40.0;
    s.handshake_timeout_s = 5.0;
    s.idle_timeout_s = 30.0;
    s.shutdown_grace_s = 2.0;
    return s;
}

class SocketTest : public ::testing::Test {
protected:
    void start(ServerSettings settings = test_settings(), BotFactory bots = {}) {
        server_ = std::make_unique<Server>(settings, std::move(bots));
        port_ = server_->listen();
        server_->start();
    }
    void TearDown() override { server_.reset(); }

    std::unique_ptr<WsTestClient> connect(const std::string& name) {
        auto client = std::make_unique<WsTestClient>(port_);
        client->send(proto::Hello{proto::kProtocolVersion, name, std::nullopt});
        welcome_ = client->wait_for<proto::Welcome>();
        EXPECT_TRUE(welcome_);
        return client;
    }

    // A and B seated in an icf room; returns the room code.
    std::string start_match(WsTestClient& a, WsTestClient& b) {
        a.send(proto::CreateRoom{});
        const auto created = a.wait_for<proto::RoomState>();
        EXPECT_TRUE(created);
        b.send(proto::JoinRoom{created->code, proto::Role::Player});
        const auto joined = b.wait_for<proto::RoomState>();
        EXPECT_TRUE(joined);
        EXPECT_EQ(joined->you, 1);
        EXPECT_TRUE(a.wait_for_event<proto::TurnEvent>());
        EXPECT_TRUE(b.wait_for_event<proto::TurnEvent>());
        return created->code;
    }

    // GET over plain HTTP/1.1: "<status> <body>" (socket_fixture.cpp).
    std::string http_get(const std::string& target);

    std::unique_ptr<Server> server_;
    std::uint16_t port_ = 0;
    std::optional<proto::Welcome> welcome_;
};

} // namespace carrom::server::testing
