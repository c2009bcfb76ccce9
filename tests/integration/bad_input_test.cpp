// Every kind of bad input gets its error code; the sender's connection (or at worst only the
// sender's connection) suffers, and the match goes on.
#include "harness.hpp"

#include "carrom/proto/codec.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/stream.hpp>
#include <gtest/gtest.h>

namespace carrom::integration {
namespace {

using namespace std::chrono_literals;

// Two seated players and a spectator in a freestyle room, seat 0 to play.
struct Table {
    explicit Table(const std::string& url) : a(url, "alice"), b(url, "bob"), s(url, "sam") {
        a.hello();
        proto::CreateRoom create;
        create.rule_set = proto::RuleSet::Freestyle;
        create.options.shot_clock_s = 0.0;
        a.send(create);
        code = a.next<proto::RoomState>().value_or(proto::RoomState{}).code;
        s.hello();
        s.send(proto::JoinRoom{code, proto::Role::Spectator});
        EXPECT_TRUE(s.next<proto::RoomState>());
        b.hello();
        b.send(proto::JoinRoom{code, proto::Role::Player});
        const auto turn = a.next_event<proto::TurnEvent>();
        EXPECT_TRUE(turn);
        turn_number = turn ? turn->turn : 0;
        EXPECT_EQ(turn ? turn->seat : -1, 0);
        b.drain(100ms);
        s.drain(100ms);
    }
    ManualClient a;
    ManualClient b;
    ManualClient s;
    std::string code;
    int turn_number = 0;
};

std::string shoot_text(int turn, const std::string& x, const std::string& power = "15") {
    return R"({"type":"shoot","turn":)" + std::to_string(turn) + R"(,"x":)" + x +
           R"(,"angle":-1.5707963,"power":)" + power + "}";
}

int errors_in(const ManualClient& client) {
    int n = 0;
    for (const auto& m : client.history()) {
        n += std::holds_alternative<proto::Error>(m) ? 1 : 0;
    }
    return n;
}

TEST(BadInput, EachGetsItsCodeAndTheMatchGoesOn) {
    TestServer server;
    Table table(server.url());
    const int t = table.turn_number;
    struct Case {
        std::string text;
        std::string code;
    };
    const std::vector<Case> cases = {
        {"this is not json", "malformed_json"},
        {shoot_text(t, "NaN"), "malformed_json"},
        {shoot_text(t, "1e400"), "malformed_json"},
        {shoot_text(t, "300", "-Infinity"), "malformed_json"},
        {"[1,2,3]", "not_object"},
        {R"({"nope":1})", "missing_type"},
        {R"({"type":7})", "missing_type"},
        {R"({"type":"warp"})", "unknown_type"},
        {R"({"type":"shoot","turn":"0","x":300,"angle":-1,"power":10})", "bad_field"},
        {R"({"type":"shoot","turn":0.5,"x":300,"angle":-1,"power":10})", "bad_field"},
        {shoot_text(t, "1e9"), "bad_field"},
        {shoot_text(t, "300", "1e300"), "bad_field"},
        {R"({"type":"join_room","code":"0O0O0O"})", "bad_field"},
        {R"({"type":"hello","version":1,"name":"again"})", "already_hello"},
        {R"({"type":"create_room"})", "already_in_room"},
        {shoot_text(t + 5, "300"), "stale_turn"},
        {shoot_text(t, "20"), "illegal_placement"},
        {shoot_text(t, "300", "30"), "illegal_shot"},
    };
    for (const auto& c : cases) {
        table.a.send_text(c.text);
        EXPECT_EQ(table.a.next_error(), c.code) << c.text;
    }
    table.b.send_text(shoot_text(t, "300"));
    EXPECT_EQ(table.b.next_error(), "not_your_turn");
    table.s.send_text(shoot_text(t, "300"));
    EXPECT_EQ(table.s.next_error(), "spectator");

    // Nobody else heard about those errors, and the same player's good shot is played.
    table.b.drain(50ms);
    table.s.drain(50ms);
    EXPECT_EQ(errors_in(table.b), 1);
    EXPECT_EQ(errors_in(table.s), 1);
    // A double click: the same shot twice. It is played once; the copy is refused.
    table.a.send(proto::Shoot{t, 300.0, -1.5707963, 15.0});
    table.a.send(proto::Shoot{t, 300.0, -1.5707963, 15.0});
    const std::string copy_error = table.a.next_error();
    EXPECT_TRUE(copy_error == "in_motion" || copy_error == "stale_turn") << copy_error;
    for (auto* client : {&table.a, &table.b, &table.s}) {
        const auto result = client->next<proto::ShotResult>(20s);
        ASSERT_TRUE(result);
        EXPECT_EQ(result->turn, t);
        EXPECT_EQ(result->seat, 0);
    }
    const auto next_turn = table.a.next_event<proto::TurnEvent>();
    ASSERT_TRUE(next_turn);
    EXPECT_EQ(next_turn->turn, t + 1);
    table.a.drain(100ms);
    int results = 0;
    for (const auto& m : table.a.history()) {
        results += std::holds_alternative<proto::ShotResult>(m) ? 1 : 0;
    }
    EXPECT_EQ(results, 1);
}

TEST(Emote, ReachesEveryMemberWithTheSendersSeat) {
    TestServer server;
    Table table(server.url());
    table.b.send(proto::EmoteMessage{proto::Emote::GoodLuck});
    const proto::EmoteEvent expected{1, proto::Emote::GoodLuck};
    for (auto* client : {&table.a, &table.b, &table.s}) {
        const auto emote = client->next_event<proto::EmoteEvent>();
        ASSERT_TRUE(emote);
        EXPECT_EQ(*emote, expected);
    }
}

TEST(Emote, UnknownNameIsABadFieldAndSpectatorsAreRefused) {
    TestServer server;
    Table table(server.url());
    table.a.send_text(R"({"type":"emote","emote":"hurry_up"})");
    EXPECT_EQ(table.a.next_error(), "bad_field");
    table.s.send(proto::EmoteMessage{proto::Emote::Wow});
    EXPECT_EQ(table.s.next_error(), "spectator");
    table.b.drain(100ms);
    for (const auto& m : table.b.history()) {
        const auto* event = std::get_if<proto::Event>(&m);
        EXPECT_FALSE(event != nullptr && std::holds_alternative<proto::EmoteEvent>(*event));
    }
}

TEST(Emote, ABurstOverTheLimitIsTooFastAndTheMatchGoesOn) {
    TestServer server;
    Table table(server.url());
    for (int i = 0; i < 4; ++i) {
        table.a.send(proto::EmoteMessage{proto::Emote::Oops});
    }
    EXPECT_EQ(table.a.next_error(), "emote_too_fast");
    int heard = 0;
    for (int i = 0; i < 4 && table.b.next_event<proto::EmoteEvent>(500ms); ++i) {
        ++heard;
    }
    EXPECT_EQ(heard, 3);
    table.a.send(proto::Shoot{table.turn_number, 300.0, -1.5707963, 15.0});
    const auto result = table.b.next<proto::ShotResult>(20s);
    ASSERT_TRUE(result);
    EXPECT_EQ(result->seat, 0);
}

TEST(BadInput, MessageBeforeHello) {
    TestServer server;
    ManualClient client(server.url());
    client.send(proto::Ping{1});
    EXPECT_EQ(client.next_error(), "hello_required");
    client.hello(); // still usable
}

TEST(BadInput, WrongTokenIsRefusedAndANewPlayerWelcomed) {
    TestServer server;
    ManualClient client(server.url());
    client.send(proto::Hello{proto::kProtocolVersion, "mallory", std::string(32, 'a')});
    EXPECT_EQ(client.next_error(), "bad_token");
    const auto welcome = client.next<proto::Welcome>();
    ASSERT_TRUE(welcome);
    EXPECT_NE(welcome->resume_token, std::string(32, 'a'));
}

TEST(BadInput, OtherProtocolVersionIsClosedWith4001) {
    TestServer server;
    ManualClient client(server.url());
    client.send(proto::Hello{proto::kProtocolVersion + 1, "future", std::nullopt});
    EXPECT_EQ(client.next_error(), "version_mismatch");
    EXPECT_NE(client.wait_closed().find("code 4001"), std::string::npos);
}

TEST(BadInput, OversizedFrameIsClosedWith1009) {
    TestServer server;
    ManualClient client(server.url());
    client.hello();
    client.send_text(R"({"type":"ping","nonce":1,"pad":")" + std::string(5000, 'x') + "\"}");
    EXPECT_EQ(client.next_error(), "too_large");
    EXPECT_NE(client.wait_closed().find("code 1009"), std::string::npos);
}

TEST(BadInput, FloodIsRateLimitedThenClosedWith1008) {
    TestServer server;
    ManualClient bystander(server.url(), "bystander");
    bystander.hello();
    ManualClient client(server.url());
    client.hello();
    for (int i = 0; i < 400; ++i) {
        client.send(proto::Ping{i});
    }
    EXPECT_EQ(client.next_error(), "rate_limited");
    EXPECT_NE(client.wait_closed().find("code 1008"), std::string::npos);
    // Someone else on the server is unaffected.
    bystander.send(proto::Ping{77});
    const auto pong = bystander.next<proto::Pong>();
    ASSERT_TRUE(pong);
    EXPECT_EQ(pong->nonce, 77);
}

TEST(BadInput, BinaryFrameIsClosedWith1003) {
    namespace asio = boost::asio;
    namespace websocket = boost::beast::websocket;
    TestServer server;
    const auto port = static_cast<std::uint16_t>(std::stoi(server.url().substr(15)));
    asio::io_context ioc;
    websocket::stream<asio::ip::tcp::socket> ws(ioc);
    ws.next_layer().connect({asio::ip::make_address("127.0.0.1"), port});
    ws.handshake("127.0.0.1", "/");
    ws.text(true);
    ws.write(asio::buffer(proto::encode(proto::Hello{proto::kProtocolVersion, "bin", {}})));
    ws.binary(true);
    ws.write(asio::buffer(std::string(R"({"type":"ping","nonce":1})")));
    std::vector<std::string> errors;
    boost::beast::error_code ec;
    for (int i = 0; i < 10 && !ec; ++i) {
        boost::beast::flat_buffer buffer;
        ws.read(buffer, ec);
        if (!ec) {
            const auto decoded =
                proto::decode_server(boost::beast::buffers_to_string(buffer.data()));
            if (decoded.ok() && std::holds_alternative<proto::Error>(*decoded.message)) {
                errors.push_back(std::get<proto::Error>(*decoded.message).code);
            }
        }
    }
    EXPECT_EQ(ec, websocket::error::closed);
    EXPECT_EQ(ws.reason().code, 1003);
    EXPECT_EQ(errors, std::vector<std::string>{"binary_frame"});
}

} // namespace
} // namespace carrom::integration
