// The real server on 127.0.0.1 with an ephemeral port, driven over real WebSocket connections.
#include "server/socket_fixture.hpp"

#include <gtest/gtest.h>

#include <thread>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using testing::kUp;
using testing::SocketTest;
using testing::WsTestClient;

TEST_F(SocketTest, HealthAndMetricsOverPlainHttp) {
    start();
    EXPECT_EQ(http_get("/healthz"), "200 ok\n");
    const std::string metrics = http_get("/metrics");
    EXPECT_EQ(metrics.rfind("200 ", 0), 0U);
    EXPECT_NE(metrics.find("carrom_connections 0"), std::string::npos);
    EXPECT_NE(metrics.find("carrom_snapshot_lag_seconds_count"), std::string::npos);
    EXPECT_EQ(http_get("/elsewhere").substr(0, 3), "404");
}

TEST_F(SocketTest, HelloCreateJoinShootStreamsToPlayersAndSpectators) {
    start();
    auto a = connect("Asha");
    auto b = connect("Bo");
    auto c = connect("Cy");
    const std::string code = start_match(*a, *b);
    c->send(proto::JoinRoom{code, proto::Role::Spectator});
    const auto watching = c->wait_for<proto::RoomState>();
    ASSERT_TRUE(watching);
    EXPECT_EQ(watching->you, -1);
    const auto keyframe = c->wait_for<proto::Snapshot>();
    ASSERT_TRUE(keyframe);
    EXPECT_TRUE(keyframe->keyframe);
    EXPECT_EQ(keyframe->bodies.size(), 20U);

    a->send(proto::Shoot{0, 300.0, kUp, 9.0});
    const auto result_b = b->wait_for<proto::ShotResult>(15000ms);
    ASSERT_TRUE(result_b);
    EXPECT_EQ(result_b->turn, 0);
    const auto result_c = c->wait_for<proto::ShotResult>(15000ms);
    ASSERT_TRUE(result_c);
    EXPECT_EQ(*result_c, *result_b);
    auto snaps_b = b->logged<proto::Snapshot>();
    auto snaps_c = c->logged<proto::Snapshot>();
    ASSERT_GT(snaps_b.size(), 10U);
    ASSERT_TRUE(snaps_b.front().keyframe && snaps_c.front().keyframe);
    snaps_b.erase(snaps_b.begin()); // the join keyframes
    snaps_c.erase(snaps_c.begin());
    ASSERT_EQ(snaps_c.size(), snaps_b.size());
    EXPECT_TRUE(snaps_c == snaps_b); // a spectator receives the same snapshots
    for (std::size_t i = 1; i < snaps_b.size(); ++i) {
        EXPECT_EQ(snaps_b[i].seq, snaps_b[i - 1].seq + 1);
    }
    EXPECT_TRUE(snaps_b.back().keyframe);
    // Real time: the shot's snapshots cover its duration, at the default 10 Hz plus one at
    // every change of motion, in time order.
    const double duration = snaps_b.back().t_s;
    EXPECT_GT(duration, 0.3);
    EXPECT_GE(static_cast<double>(snaps_b.size() - 1), duration * 10.0);
    for (std::size_t i = 1; i < snaps_b.size(); ++i) {
        EXPECT_GE(snaps_b[i].t_s, snaps_b[i - 1].t_s);
        EXPECT_LE(snaps_b[i].t_s - snaps_b[i - 1].t_s, 0.1 + 0.2); // a loaded machine is late
    }
    const auto state = b->wait_for<proto::RoomState>();
    ASSERT_TRUE(state);
    EXPECT_EQ(state->turn, 1);
}

TEST_F(SocketTest, BadInputsGetTheirErrorsAndTheMatchGoesOn) {
    start();
    auto a = connect("Asha");
    auto b = connect("Bo");
    auto c = connect("Cy");
    const std::string code = start_match(*a, *b);
    c->send(proto::JoinRoom{code, proto::Role::Spectator});
    ASSERT_TRUE(c->wait_for<proto::RoomState>());

    a->send_text("{not json");
    EXPECT_EQ(a->wait_for_error(), "malformed_json");
    a->send_text(R"({"type":"shoot","turn":"0","x":300,"angle":0,"power":5})");
    EXPECT_EQ(a->wait_for_error(), "bad_field");
    a->send_text(R"({"type":"warp","x":1})");
    EXPECT_EQ(a->wait_for_error(), "unknown_type");
    a->send_text(R"({"type":"shoot","turn":0,"x":1e400,"angle":0,"power":5})");
    EXPECT_EQ(a->wait_for_error(), "malformed_json");
    a->send_text(R"({"type":"shoot","turn":0,"x":NaN,"angle":0,"power":5})");
    EXPECT_EQ(a->wait_for_error(), "malformed_json");
    a->send_text(R"({"type":"shoot","turn":0,"x":300,"angle":0,"power":1e300})");
    EXPECT_EQ(a->wait_for_error(), "bad_field");
    a->send(proto::Shoot{0, 20.0, kUp, 10.0});
    EXPECT_EQ(a->wait_for_error(), "illegal_placement");
    b->send(proto::Shoot{0, 300.0, -kUp, 10.0});
    EXPECT_EQ(b->wait_for_error(), "not_your_turn");
    a->send(proto::Shoot{7, 300.0, kUp, 10.0});
    EXPECT_EQ(a->wait_for_error(), "stale_turn");
    c->send(proto::Shoot{0, 300.0, kUp, 10.0});
    EXPECT_EQ(c->wait_for_error(), "spectator");

    // Nothing above changed the match: the real shot plays turn 0.
    a->send(proto::Shoot{0, 300.0, kUp, 9.0});
    const auto result = b->wait_for<proto::ShotResult>(15000ms);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->turn, 0);
    // A retried shot for the played turn is never played twice.
    a->send(proto::Shoot{0, 300.0, kUp, 9.0});
    const std::string retry = a->wait_for_error();
    EXPECT_TRUE(retry == "stale_turn" || retry == "not_your_turn") << retry;
}

TEST_F(SocketTest, AFixedLengthFieldSaysItsExactLength) {
    start();
    auto a = connect("Asha");
    a->send_text(R"({"type":"join_room","code":"ABCDE"})");
    const auto error = a->wait_for<proto::Error>();
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "bad_field");
    EXPECT_EQ(error->message, "field 'code' must be exactly 6 bytes long.");
    a->send_text(R"({"type":"hello","version":1,"name":""})");
    const auto name = a->wait_for<proto::Error>();
    ASSERT_TRUE(name);
    EXPECT_NE(name->message.find(" to "), std::string::npos) << name->message;
}

TEST_F(SocketTest, HelloRules) {
    start();
    WsTestClient early(port_);
    early.send(proto::Ping{1});
    EXPECT_EQ(early.wait_for_error(), "hello_required");
    early.send(proto::Hello{proto::kProtocolVersion + 1, "Future", std::nullopt});
    EXPECT_EQ(early.wait_for_error(), "version_mismatch");
    EXPECT_EQ(early.wait_for_close(), proto::kCloseVersionMismatch);

    WsTestClient token(port_);
    token.send(proto::Hello{proto::kProtocolVersion, "T", std::string(32, 'a')});
    EXPECT_EQ(token.wait_for_error(), "bad_token");
    EXPECT_TRUE(token.wait_for<proto::Welcome>()); // joins as a new player
    token.send(proto::Hello{proto::kProtocolVersion, "T", std::nullopt});
    EXPECT_EQ(token.wait_for_error(), "already_hello");
    token.send(proto::JoinRoom{"ZZZZZZ", proto::Role::Player});
    EXPECT_EQ(token.wait_for_error(), "room_not_found");
    token.send(proto::Shoot{0, 300.0, kUp, 1.0});
    EXPECT_EQ(token.wait_for_error(), "not_in_room");
    token.send(proto::CreateRoom{proto::RuleSet::Icf, {}, proto::BotSeat{proto::BotLevel::Hard}});
    EXPECT_EQ(token.wait_for_error(), "unsupported");
}

TEST_F(SocketTest, DroppedPlayerResumesMidShotWithItsToken) {
    start();
    auto a = connect("Asha");
    auto b = connect("Bo");
    const auto b_welcome = *welcome_;
    start_match(*a, *b);
    a->send(proto::Shoot{0, 300.0, kUp, 9.0});
    ASSERT_TRUE(b->wait_for<proto::Snapshot>());
    b->drop();
    const auto dropped = a->wait_for_event<proto::PlayerDroppedEvent>();
    ASSERT_TRUE(dropped);
    EXPECT_EQ(dropped->seat, 1);
    EXPECT_EQ(dropped->grace_deadline_ms - dropped->server_time_ms, 60000);

    WsTestClient b2(port_);
    b2.send(proto::Hello{proto::kProtocolVersion, "Bo", b_welcome.resume_token});
    const auto again = b2.wait_for<proto::Welcome>();
    ASSERT_TRUE(again);
    EXPECT_EQ(again->player_id, b_welcome.player_id);
    EXPECT_EQ(again->resume_token, b_welcome.resume_token);
    const auto state = b2.wait_for<proto::RoomState>();
    ASSERT_TRUE(state);
    EXPECT_EQ(state->you, 1);
    const auto keyframe = b2.wait_for<proto::Snapshot>();
    ASSERT_TRUE(keyframe);
    EXPECT_TRUE(keyframe->keyframe);
    EXPECT_TRUE(a->wait_for_event<proto::PlayerReturnedEvent>());
    const auto result = b2.wait_for<proto::ShotResult>(15000ms);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->turn, 0);
}

TEST_F(SocketTest, ShutdownTellsClientsAndCloses) {
    start();
    auto a = connect("Asha");
    std::thread stopper([this] { server_->shutdown(); });
    EXPECT_EQ(a->wait_for_error(), "shutting_down");
    EXPECT_EQ(a->wait_for_close(), proto::kCloseRestarting);
    stopper.join();
}

} // namespace
} // namespace carrom::server
