// The server under pressure: slow readers, spectator churn, floods, connection and room caps,
// handshake and idle timeouts; the offender is closed with its code, the others play on.
#include "server/socket_fixture.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using testing::kUp;
using testing::SocketTest;
using testing::test_settings;
using testing::WsTestClient;

// A client that stops reading while pongs pile up overflows its write queue: it is counted once
// as a slow client and, reading again, finds the close frame 4003 after what was in flight.
TEST_F(SocketTest, SlowClientGetsClose4003AndIsCountedOnce) {
    auto settings = test_settings();
    settings.max_queue_bytes = 16384;
    settings.max_rate = 100000.0;
    settings.rate_burst = 1000000.0;
    start(settings);
    const auto slow_count = [&] { return server_->metrics().slow_client_disconnects_total.load(); };
    for (int k = 0; k < 3; ++k) {
        auto slow = std::make_unique<WsTestClient>(port_, 2048);
        slow->send(proto::Hello{proto::kProtocolVersion, "Slow", std::nullopt});
        std::int64_t nonce = 0;
        while (slow_count() == k && nonce < 2000000) {
            for (int i = 0; i < 200; ++i) {
                slow->send(proto::Ping{++nonce});
            }
        }
        ASSERT_EQ(slow_count(), k + 1) << "no overflow after " << nonce << " pings";
        // More input after the overflow neither counts again nor queues anything.
        for (int i = 0; i < 200; ++i) {
            if (!slow->try_send_text(proto::encode(proto::ClientMessage{proto::Ping{++nonce}}))) {
                break;
            }
        }
        EXPECT_EQ(slow->wait_for_close(), proto::kCloseSlowClient);
        EXPECT_EQ(slow_count(), k + 1);
    }
    auto ok = connect("Ok");
    ok->send(proto::Ping{1});
    EXPECT_TRUE(ok->wait_for<proto::Pong>());
}

// Spectators joining and leaving under the rate limit used to send every player a full
// room_state each time (about 3.4 KB): a player on a slow link was dropped. Now they send the
// players nothing, and the slow player's match goes on.
TEST_F(SocketTest, SpectatorChurnLeavesASlowPlayerConnected) {
    auto settings = test_settings();
    settings.max_queue_bytes = 16384;
    start(settings);
    auto a = connect("Asha");
    auto b = std::make_unique<WsTestClient>(port_, 2048);
    b->send(proto::Hello{proto::kProtocolVersion, "Bo", std::nullopt});
    ASSERT_TRUE(b->wait_for<proto::Welcome>());
    const std::string code = start_match(*a, *b);
    std::vector<std::unique_ptr<WsTestClient>> churners;
    for (int i = 0; i < 5; ++i) {
        churners.push_back(connect("Watcher"));
    }
    // b reads nothing while 5 spectators join and leave 20 times a second each for 2 s.
    for (int round = 0; round < 40; ++round) {
        for (auto& c : churners) {
            c->send(proto::JoinRoom{code, proto::Role::Spectator});
            ASSERT_TRUE(c->wait_for<proto::RoomState>());
            c->send(proto::Leave{});
        }
        std::this_thread::sleep_for(50ms);
    }
    EXPECT_EQ(server_->metrics().slow_client_disconnects_total.load(), 0);
    b->send(proto::Ping{3});
    const auto pong = b->wait_for<proto::Pong>();
    ASSERT_TRUE(pong);
    EXPECT_EQ(pong->nonce, 3);
    a->send(proto::Shoot{0, 300.0, kUp, 25.0});
    EXPECT_TRUE(b->wait_for<proto::ShotResult>(20s));
    EXPECT_EQ(server_->metrics().slow_client_disconnects_total.load(), 0);
}

TEST_F(SocketTest, FloodIsRateLimitedThenClosedAndOthersAreUnaffected) {
    start();
    auto a = connect("Asha");
    auto b = connect("Bo");
    start_match(*a, *b);
    auto flood = connect("Flood");
    for (int i = 0; i < 200; ++i) {
        flood->send(proto::Ping{i});
    }
    EXPECT_EQ(flood->wait_for_error(), "rate_limited");
    EXPECT_EQ(flood->wait_for_close(), proto::kClosePolicy);
    a->send(proto::Shoot{0, 300.0, kUp, 9.0});
    EXPECT_TRUE(b->wait_for<proto::ShotResult>(15000ms));
}

TEST_F(SocketTest, ConnectionAndRoomLimits) {
    ServerSettings s = test_settings();
    s.max_connections = 2;
    s.max_rooms = 1;
    start(s);
    auto a = connect("Asha");
    auto b = connect("Bo");
    WsTestClient third(port_);
    EXPECT_EQ(third.wait_for_error(), "server_full");
    EXPECT_EQ(third.wait_for_close(), proto::kCloseTryAgainLater);
    a->send(proto::CreateRoom{});
    ASSERT_TRUE(a->wait_for<proto::RoomState>());
    b->send(proto::CreateRoom{});
    EXPECT_EQ(b->wait_for_error(), "too_many_rooms");
}

TEST_F(SocketTest, ConnectionsPerAddressAreCapped) {
    ServerSettings s = test_settings();
    s.max_connections_per_address = 3;
    start(s);
    auto a = connect("Asha");
    auto b = connect("Bo");
    auto c = connect("Cy");
    WsTestClient fourth(port_);
    EXPECT_EQ(fourth.wait_for_error(), "too_many_connections");
    EXPECT_EQ(fourth.wait_for_close(), proto::kClosePolicy);
    // A closed connection frees its place (once the server has seen it end).
    a->drop();
    bool welcomed = false;
    for (int i = 0; i < 50 && !welcomed; ++i) {
        WsTestClient next(port_);
        next.send(proto::Hello{proto::kProtocolVersion, "Dee", std::nullopt});
        const auto reply = next.read();
        welcomed = reply && std::holds_alternative<proto::Welcome>(*reply);
        if (!welcomed) {
            std::this_thread::sleep_for(20ms);
        }
    }
    EXPECT_TRUE(welcomed);
}

TEST_F(SocketTest, HandshakeAndIdleTimeouts) {
    ServerSettings s = test_settings();
    s.handshake_timeout_s = 0.2;
    s.idle_timeout_s = 0.4;
    start(s);
    WsTestClient silent(port_);
    EXPECT_EQ(silent.wait_for_error(), "handshake_timeout");
    EXPECT_EQ(silent.wait_for_close(), proto::kClosePolicy);

    // A client that neither sends nor reads (so it answers no keep-alive ping) is closed.
    auto idle = connect("Idle");
    std::this_thread::sleep_for(800ms);
    EXPECT_EQ(idle->wait_for_error(), "idle_timeout");
    EXPECT_EQ(idle->wait_for_close(), proto::kClosePolicy);
}

TEST_F(SocketTest, KeepAlivePingsKeepAReadingClientOpen) {
    ServerSettings s = test_settings();
    s.idle_timeout_s = 0.4;
    start(s);
    auto a = connect("Asha");
    // Reading answers the server's pings; a long wait for a message that never comes must time
    // out on our side, not end in the server's idle close.
    EXPECT_FALSE(a->read(1200ms));
    EXPECT_TRUE(a->logged<proto::Error>().empty());
    EXPECT_EQ(server_->metrics().connections.load(), 1);
}

} // namespace
} // namespace carrom::server
