// The real server on 127.0.0.1 with an ephemeral port, driven over real WebSocket connections.
#include "carrom/server/server.hpp"

#include "server/ws_test_client.hpp"

#include <boost/beast/http.hpp>
#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <numbers>
#include <thread>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using testing::WsTestClient;

constexpr double kUp = -std::numbers::pi / 2.0;

ServerSettings test_settings() {
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

    std::string http_get(const std::string& target) {
        namespace http = boost::beast::http;
        boost::asio::io_context ioc;
        boost::beast::tcp_stream stream(ioc);
        stream.connect(
            boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port_));
        http::request<http::empty_body> request{http::verb::get, target, 11};
        request.set(http::field::host, "127.0.0.1");
        http::write(stream, request);
        boost::beast::flat_buffer buffer;
        http::response<http::string_body> response;
        http::read(stream, buffer, response);
        return std::to_string(response.result_int()) + " " + response.body();
    }

    std::unique_ptr<Server> server_;
    std::uint16_t port_ = 0;
    std::optional<proto::Welcome> welcome_;
};

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
    // Real time: the shot's snapshots cover its duration at about 60 Hz.
    const double duration = snaps_b.back().t_s;
    EXPECT_GT(duration, 0.3);
    EXPECT_NEAR(static_cast<double>(snaps_b.size() - 1), duration * 60.0,
                duration * 60.0 * 0.2 + 3);
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

TEST_F(SocketTest, OversizedAndBinaryFramesCloseWithPolicyCodes) {
    start();
    auto big = connect("Big");
    big->send_text(R"({"type":"ping","nonce":1,"pad":")" + std::string(5000, 'x') + "\"}");
    EXPECT_EQ(big->wait_for_error(), "too_large");
    EXPECT_EQ(big->wait_for_close(), proto::kCloseTooBig);

    auto bin = connect("Bin");
    bin->send_binary(std::string("\x01\x02\x03", 3));
    EXPECT_EQ(bin->wait_for_error(), "binary_frame");
    EXPECT_EQ(bin->wait_for_close(), proto::kCloseUnsupportedData);

    auto ok = connect("Ok");
    ok->send(proto::Ping{5});
    const auto pong = ok->wait_for<proto::Pong>();
    ASSERT_TRUE(pong);
    EXPECT_EQ(pong->nonce, 5);
}

// RFC 6455 has the receiver of invalid UTF-8 in a text frame fail the connection, and Beast
// does so before the server sees the message: close 1007 with no error (docs/protocol.md).
TEST_F(SocketTest, InvalidUtf8TextFrameClosesWith1007AndNoError) {
    start();
    auto bad = connect("Utf");
    bad->send_text("{\"type\":\"ping\",\"nonce\":1,\"pad\":\"\xff\xfe\"}");
    EXPECT_EQ(bad->wait_for_close(), 1007);
    EXPECT_TRUE(bad->logged<proto::Error>().empty());

    auto ok = connect("Ok");
    ok->send(proto::Ping{7});
    EXPECT_TRUE(ok->wait_for<proto::Pong>());
}

// With the default 4096-byte limit a message of up to 65536 bytes is read whole and answered
// with too_large; one byte more is cut off by the WebSocket layer: close 1009 alone.
TEST_F(SocketTest, HardFrameCutOffIsMaxOfFourTimesTheLimitAnd64KiB) {
    start();
    const std::string head = R"({"type":"ping","nonce":1,"pad":")";
    const auto padded = [&](std::size_t size) {
        return head + std::string(size - head.size() - 2, 'x') + "\"}";
    };
    auto at = connect("At");
    ASSERT_EQ(padded(65536).size(), 65536U);
    at->send_text(padded(65536));
    EXPECT_EQ(at->wait_for_error(), "too_large");
    EXPECT_EQ(at->wait_for_close(), proto::kCloseTooBig);

    auto over = connect("Over");
    (void)over->try_send_text(padded(65537));
    EXPECT_EQ(over->wait_for_close(), proto::kCloseTooBig);
    EXPECT_TRUE(over->logged<proto::Error>().empty());

    // The cut-off follows a larger limit: 4 x 20000 bytes.
    server_.reset();
    auto settings = test_settings();
    settings.max_message_bytes = 20000;
    start(settings);
    auto big = connect("Big");
    big->send_text(padded(80000));
    EXPECT_EQ(big->wait_for_error(), "too_large");
    EXPECT_EQ(big->wait_for_close(), proto::kCloseTooBig);
    auto bigger = connect("Bigger");
    (void)bigger->try_send_text(padded(80001));
    EXPECT_EQ(bigger->wait_for_close(), proto::kCloseTooBig);
    EXPECT_TRUE(bigger->logged<proto::Error>().empty());
}

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

TEST_F(SocketTest, QuickMatchPairsTwoWaitingPlayers) {
    start();
    auto a = connect("Asha");
    auto b = connect("Bo");
    a->send(proto::QuickMatch{proto::RuleSet::Seed});
    b->send(proto::QuickMatch{proto::RuleSet::Seed});
    ASSERT_TRUE(a->wait_for_event<proto::TurnEvent>());
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    const auto room_a = a->logged<proto::RoomState>().back();
    const auto room_b = b->logged<proto::RoomState>().back();
    EXPECT_EQ(room_a.rule_set, proto::RuleSet::Seed);
    EXPECT_EQ(room_a.code, room_b.code);
    EXPECT_NE(room_a.you, room_b.you);
}

// A server bot that always plays a soft shot along its baseline, and counts the brains made.
class SoftShotBrain final : public room::BotBrain {
public:
    Shot choose_shot(const rules::MatchState&, int, std::chrono::milliseconds) override {
        return {300.0, 0.0, 2.0};
    }
};

struct CountingBots {
    std::shared_ptr<std::atomic<int>> made = std::make_shared<std::atomic<int>>(0);
    std::shared_ptr<std::atomic<int>> last_level = std::make_shared<std::atomic<int>>(-1);
    BotFactory factory() const {
        return [count = made, level_seen = last_level](proto::BotLevel level) {
            ++*count;
            *level_seen = static_cast<int>(level);
            return std::make_shared<SoftShotBrain>();
        };
    }
};

ServerSettings quick_bot_settings(double wait_s) {
    ServerSettings s = test_settings();
    s.quick_match_bot_s = wait_s;
    s.time_scale = 10.0; // shots play fast
    return s;
}

TEST_F(SocketTest, QuickMatchSeatsABotAfterTheWaitAndTheBotPlays) {
    CountingBots bots;
    ServerSettings s = quick_bot_settings(0.2);
    s.quick_match_bot_level = proto::BotLevel::Hard;
    start(s, bots.factory());
    auto a = connect("Asha");
    const auto asked = std::chrono::steady_clock::now();
    a->send(proto::QuickMatch{proto::RuleSet::Freestyle});
    std::optional<proto::RoomState> state;
    for (int i = 0; i < 4 && !(state && state->seats[1].bot); ++i) {
        state = a->wait_for<proto::RoomState>(3000ms);
        ASSERT_TRUE(state);
    }
    ASSERT_TRUE(state && state->seats[1].bot);
    EXPECT_GE(std::chrono::steady_clock::now() - asked, 190ms); // not before the wait
    EXPECT_EQ(state->you, 0);
    EXPECT_EQ(state->rule_set, proto::RuleSet::Freestyle);
    EXPECT_EQ(state->seats[1].name, "Bot (hard)");
    EXPECT_EQ(*bots.made, 1);
    EXPECT_EQ(*bots.last_level, static_cast<int>(proto::BotLevel::Hard));
    const auto turn = a->wait_for_event<proto::TurnEvent>();
    ASSERT_TRUE(turn);
    ASSERT_EQ(turn->seat, 0);
    a->send(proto::Shoot{turn->turn, 300.0, 0.0, 2.0}); // soft, along the baseline: bot's turn
    const auto mine = a->wait_for<proto::ShotResult>(5000ms);
    ASSERT_TRUE(mine);
    EXPECT_EQ(mine->seat, 0);
    EXPECT_EQ(mine->next_seat, 1);
    const auto bots_shot = a->wait_for<proto::ShotResult>(5000ms); // the bot shoots by itself
    ASSERT_TRUE(bots_shot);
    EXPECT_EQ(bots_shot->seat, 1);
    EXPECT_EQ(bots_shot->turn, mine->next_turn);
}

TEST_F(SocketTest, QuickMatchPartnerBeforeTheWaitMeansNoBot) {
    CountingBots bots;
    start(quick_bot_settings(0.3), bots.factory());
    auto a = connect("Asha");
    auto b = connect("Bo");
    a->send(proto::QuickMatch{proto::RuleSet::Icf});
    b->send(proto::QuickMatch{proto::RuleSet::Icf});
    ASSERT_TRUE(a->wait_for_event<proto::TurnEvent>());
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    const auto room = a->logged<proto::RoomState>().back();
    EXPECT_FALSE(room.seats[0].bot);
    EXPECT_FALSE(room.seats[1].bot);
    EXPECT_EQ(room.code, b->logged<proto::RoomState>().back().code);
    // Past the wait: no bot room, nothing more for either player.
    EXPECT_FALSE(a->read(500ms));
    EXPECT_EQ(*bots.made, 0);
    EXPECT_EQ(server_->metrics().rooms.load(), 1);
}

TEST_F(SocketTest, QuickMatchWaitersWhoLeaveGetNoBot) {
    CountingBots bots;
    start(quick_bot_settings(0.2), bots.factory());
    auto leaver = connect("Lee");
    auto dropper = connect("Dee");
    auto creator = connect("Cy");
    leaver->send(proto::QuickMatch{proto::RuleSet::Icf});
    dropper->send(proto::QuickMatch{proto::RuleSet::Seed});
    creator->send(proto::QuickMatch{proto::RuleSet::DiscPool});
    leaver->send(proto::Leave{});
    dropper->drop();
    creator->send(proto::CreateRoom{});
    const auto own = creator->wait_for<proto::RoomState>();
    ASSERT_TRUE(own);
    EXPECT_FALSE(own->seats[1].occupied);
    EXPECT_FALSE(leaver->read(600ms)); // three waits have passed
    while (creator->read(50ms)) {      // its own room's keyframe; nobody joins it
    }
    for (const auto& state : creator->logged<proto::RoomState>()) {
        EXPECT_FALSE(state.seats[1].occupied);
    }
    EXPECT_EQ(*bots.made, 0);
    EXPECT_EQ(server_->metrics().rooms.load(), 1);
    // A waiter who left may queue again, and then does get its bot.
    auto again = connect("Al");
    again->send(proto::QuickMatch{proto::RuleSet::Icf});
    again->send(proto::Leave{});
    again->send(proto::QuickMatch{proto::RuleSet::Icf});
    std::optional<proto::RoomState> state;
    for (int i = 0; i < 4 && !(state && state->seats[1].bot); ++i) {
        state = again->wait_for<proto::RoomState>(3000ms);
        ASSERT_TRUE(state);
    }
    EXPECT_EQ(*bots.made, 1);
}

TEST_F(SocketTest, QuickMatchBotWaitZeroNeverSeatsABot) {
    CountingBots bots;
    start(quick_bot_settings(0.0), bots.factory());
    auto a = connect("Asha");
    a->send(proto::QuickMatch{proto::RuleSet::Icf});
    EXPECT_FALSE(a->read(400ms));
    EXPECT_EQ(*bots.made, 0);
    EXPECT_EQ(server_->metrics().rooms.load(), 0);
    auto b = connect("Bo"); // pairing still works
    b->send(proto::QuickMatch{proto::RuleSet::Icf});
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    const auto room = b->logged<proto::RoomState>().back();
    EXPECT_FALSE(room.seats[0].bot);
    EXPECT_FALSE(room.seats[1].bot);
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

TEST_F(SocketTest, ShutdownTellsClientsAndCloses) {
    start();
    auto a = connect("Asha");
    std::thread stopper([this] { server_->shutdown(); });
    EXPECT_EQ(a->wait_for_error(), "shutting_down");
    EXPECT_EQ(a->wait_for_close(), proto::kCloseGoingAway);
    stopper.join();
}

} // namespace
} // namespace carrom::server
