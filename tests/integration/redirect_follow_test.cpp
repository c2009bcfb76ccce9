// carrom-bot's engine (bots::BotRunner) follows a cluster's `redirect` (docs/protocol.md,
// "Redirects") against real parts: a real carrom-server program on one 127.0.0.1 port, and in
// front of it a small WebSocket server of this test (Beast) that answers like an instance that
// does not run the room: welcome, then `redirect` to the real server and close 4005. A redirect
// to another host (127.0.0.2, where a listener counts connections) is never connected to.
#include "harness.hpp"
#include "support/server_process.hpp"
#include "support/tcp_listener.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/proto/error.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/stream.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <mutex>
#include <thread>

namespace carrom::integration {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using namespace std::chrono_literals;

using test_support::TcpListener;

// An instance that runs no room: a hello with a resume token gets `redirect` (seat); one without
// gets welcome, and its room request gets `redirect` (room, the code it asked for, else
// `code`). Then close 4005. Records every hello.
class RedirectingInstance {
public:
    RedirectingInstance(std::string target, std::string code = {})
        : target_(std::move(target)), code_(std::move(code)),
          listener_("127.0.0.1", [this](tcp::socket& socket) { serve(socket); }) {}
    std::string url() const { return "ws://127.0.0.1:" + std::to_string(listener_.port()); }
    std::vector<proto::Hello> hellos() const {
        const std::lock_guard lock(mutex_);
        return hellos_;
    }

private:
    void serve(tcp::socket& socket) {
        websocket::stream<tcp::socket> ws(std::move(socket));
        beast::error_code ec;
        ws.accept(ec);
        ws.text(true);
        const auto next = [&]() -> std::optional<proto::ClientMessage> {
            beast::flat_buffer buffer;
            ws.read(buffer, ec);
            auto decoded = proto::decode_client(beast::buffers_to_string(buffer.data()));
            return !ec && decoded.ok() ? decoded.message : std::nullopt;
        };
        const auto hello = ec ? std::nullopt : next();
        if (!hello || !std::holds_alternative<proto::Hello>(*hello)) {
            return;
        }
        const proto::Hello said = std::get<proto::Hello>(*hello);
        {
            const std::lock_guard lock(mutex_);
            hellos_.push_back(said);
        }
        proto::Redirect redirect{target_, "seat", "", proto::Role::Player};
        if (!said.resume_token) {
            ws.write(asio::buffer(proto::encode(
                         proto::Welcome{proto::kProtocolVersion, 7, std::string(32, 'e'), 1})),
                     ec);
            const auto request = next();
            if (!request) {
                return;
            }
            const auto* join = std::get_if<proto::JoinRoom>(&*request);
            redirect = proto::Redirect{target_, "room", join ? join->code : code_,
                                       join ? join->as : proto::Role::Player};
        }
        ws.write(asio::buffer(proto::encode(redirect)), ec);
        ws.close(websocket::close_reason(static_cast<std::uint16_t>(proto::kCloseRedirected)), ec);
    }

    std::string target_;
    std::string code_;
    mutable std::mutex mutex_;
    std::vector<proto::Hello> hellos_;
    TcpListener listener_; // last: its thread stops before the rest goes
};

test_support::ServerProcess::Options real_server() {
    test_support::ServerProcess::Options options;
    options.program = CARROM_SERVER_PATH;
    options.args = {"--time-scale", "25", "--shot-clock", "0", "--log-level", "warn"};
    return options;
}

bots::BotConfig bot_config(const std::string& url, bots::JoinMode mode, const std::string& code) {
    bots::BotConfig config;
    config.url = url;
    config.name = mode == bots::JoinMode::Create ? "host" : "guest";
    config.mode = mode;
    config.code = code;
    config.games = 5;
    return config;
}

// Steps every runner until `until` holds or 10 s pass; true when it held.
bool step_until(const std::vector<bots::BotRunner*>& runners, const std::function<bool()>& until) {
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (!until() && std::chrono::steady_clock::now() < deadline) {
        for (bots::BotRunner* runner : runners) {
            runner->step(10ms);
        }
    }
    return until();
}

TEST(RedirectFollow, BotJoinsTheNamedRoomAndResumesItsSeatThroughRedirects) {
    test_support::ServerProcess server(real_server());
    ASSERT_TRUE(server.start()) << server.log();
    const auto strategy = test_strategy("random", 1);
    bots::BotRunner host(bot_config(server.url(), bots::JoinMode::Create, ""), *strategy);
    host.start();
    ASSERT_TRUE(step_until({&host}, [&] { return host.room().has_value(); }))
        << host.summary().failure;
    const std::string code = host.room()->code;

    RedirectingInstance front(server.url() + "/");
    bots::BotRunner guest(bot_config(front.url(), bots::JoinMode::Join, code), *strategy);
    guest.start();
    ASSERT_TRUE(step_until({&host, &guest}, [&] { return guest.room().has_value(); }))
        << guest.summary().failure;
    EXPECT_EQ(guest.summary().room_code, code);
    EXPECT_EQ(guest.summary().seat, 1);
    EXPECT_EQ(guest.summary().redirects, 1);
    const std::string token = guest.resume_token();

    // The link drops; the resume goes to the given address, which sends the seat on.
    guest.drop();
    guest.resume();
    ASSERT_TRUE(step_until({&host, &guest}, [&] { return guest.summary().resumes == 1; }))
        << guest.summary().failure;
    EXPECT_EQ(guest.summary().redirects, 2);
    EXPECT_EQ(guest.summary().seat, 1);
    EXPECT_EQ(guest.resume_token(), token);
    EXPECT_TRUE(guest.summary().failure.empty()) << guest.summary().failure;

    const std::vector<proto::Hello> hellos = front.hellos();
    ASSERT_EQ(hellos.size(), 2u);
    EXPECT_TRUE(hellos[0].follows_redirects);
    EXPECT_FALSE(hellos[0].resume_token.has_value());
    EXPECT_TRUE(hellos[1].follows_redirects);
    EXPECT_EQ(hellos[1].resume_token, token);
}

TEST(RedirectFollow, BotNeverConnectsToAnotherHost) {
    TcpListener elsewhere("127.0.0.2");
    RedirectingInstance front("ws://127.0.0.2:" + std::to_string(elsewhere.port()) + "/", "K7M2QX");
    const auto strategy = test_strategy("random", 2);
    bots::BotRunner bot(bot_config(front.url(), bots::JoinMode::Quick, ""), *strategy);
    bot.start();
    EXPECT_TRUE(bot.run_until_done(10s));
    EXPECT_EQ(bot.summary().failure,
              "redirect refused: ws://127.0.0.2:" + std::to_string(elsewhere.port()) +
                  "/ is not an address of this cluster (" + front.url() + ").");
    EXPECT_EQ(bot.summary().redirects, 0);
    std::this_thread::sleep_for(200ms);
    EXPECT_EQ(elsewhere.accepted(), 0);
    EXPECT_EQ(front.hellos().size(), 1u);
}

// carrom-load --port (the front's) for one match over `seconds` s of measuring: its exit code
// and JSON result (null when it printed none).
std::pair<int, nlohmann::json> load_through(const RedirectingInstance& front, int seconds) {
    const std::string port = front.url().substr(front.url().rfind(':') + 1);
    const CommandRun ran =
        run_command(std::string(CARROM_LOAD_PATH) + " --port " + port +
                    " --matches 1 --ramp 0 --warmup 1 --think-ms 200 --seed 3 --duration " +
                    std::to_string(seconds) + " 2>/dev/null");
    return {ran.exit, nlohmann::json::parse(ran.out, nullptr, false)};
}

// carrom-load --port FRONT: both players of its match are redirected once (the creator's
// create_room without a room code, the joiner's join_room with its code) and play on the real
// server. About 4 s.
TEST(RedirectFollow, LoadFollowsAndCountsRedirects) {
    test_support::ServerProcess server(real_server());
    ASSERT_TRUE(server.start()) << server.log();
    RedirectingInstance front(server.url() + "/");
    const auto [exit, out] = load_through(front, 2);
    ASSERT_EQ(exit, 0) << out.dump();
    EXPECT_EQ(out["redirects"], 2);
    EXPECT_EQ(out["redirects_refused"], 0);
    EXPECT_EQ(out["client_failures"], 0);
    EXPECT_EQ(out["held_at_end"], 1);
    EXPECT_EQ(front.hellos().size(), 2u);
}

TEST(RedirectFollow, LoadNeverConnectsToAnotherHost) {
    TcpListener elsewhere("127.0.0.2");
    const std::string target = "ws://127.0.0.2:" + std::to_string(elsewhere.port()) + "/";
    RedirectingInstance front(target);
    const auto [exit, out] = load_through(front, 1);
    EXPECT_EQ(exit, 1) << out.dump();
    EXPECT_EQ(out["redirects"], 0);
    EXPECT_EQ(out["redirects_refused"], 1);
    EXPECT_EQ(out["redirect_refusal"], "redirect refused: " + target +
                                           " is not an address of this cluster (" + front.url() +
                                           ").");
    EXPECT_EQ(elsewhere.accepted(), 0);
}

} // namespace
} // namespace carrom::integration
