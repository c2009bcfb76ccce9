// net::Connection against tiny in-test servers: a synchronous Beast WebSocket peer on its own
// thread (one connection each), a TCP listener that never answers, a plain HTTP responder and
// a closed port. Everything listens on 127.0.0.1 with an ephemeral port.

// Asio and Beast are compiled once in carrom_beast, which this test links (tests/CMakeLists.txt)
// for the same separate-compilation definitions.

#include "carrom/net/connection.hpp"
#include "carrom/proto/codec.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/stream.hpp>
#include <gtest/gtest.h>

#include <functional>
#include <thread>

namespace carrom::net {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using namespace std::chrono_literals;
using Peer = websocket::stream<tcp::socket>;

// Accepts one TCP connection on 127.0.0.1 and hands it to `serve` on a thread.
class OneShotServer {
public:
    explicit OneShotServer(std::function<void(tcp::socket&)> serve)
        : acceptor_(ioc_, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0)) {
        port_ = acceptor_.local_endpoint().port();
        thread_ = std::thread([this, serve = std::move(serve)] {
            tcp::socket socket(ioc_);
            beast::error_code ec;
            acceptor_.accept(socket, ec);
            if (!ec) {
                serve(socket);
            }
        });
    }
    ~OneShotServer() {
        ::shutdown(acceptor_.native_handle(), SHUT_RDWR); // wakes a pending accept
        thread_.join();
    }
    std::string url() const { return "ws://127.0.0.1:" + std::to_string(port_); }

private:
    asio::io_context ioc_;
    tcp::acceptor acceptor_;
    std::uint16_t port_ = 0;
    std::thread thread_;
};

// A WebSocket peer: accepts the upgrade, then runs `serve`.
std::function<void(tcp::socket&)> websocket_peer(std::function<void(Peer&)> serve) {
    return [serve = std::move(serve)](tcp::socket& socket) {
        Peer ws(std::move(socket));
        beast::error_code ec;
        ws.accept(ec);
        if (!ec) {
            serve(ws);
        }
    };
}

// Reads text frames until the connection ends; answers each ping with a pong.
void pong_server(Peer& ws) {
    for (;;) {
        beast::flat_buffer buffer;
        beast::error_code ec;
        ws.read(buffer, ec);
        if (ec) {
            return;
        }
        const auto decoded = proto::decode_client(beast::buffers_to_string(buffer.data()));
        if (decoded.ok()) {
            if (const auto* ping = std::get_if<proto::Ping>(&*decoded.message)) {
                ws.text(true);
                ws.write(asio::buffer(proto::encode(proto::Pong{ping->nonce, 5})), ec);
            }
        }
    }
}

ConnectionStatus wait_closed(Connection& connection, std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (connection.status().state != ConnectionState::Closed &&
           std::chrono::steady_clock::now() < deadline) {
        connection.wait(20ms);
    }
    return connection.status();
}

std::vector<proto::ServerMessage> receive(Connection& connection, std::size_t count,
                                          std::chrono::milliseconds timeout = 5s) {
    std::vector<proto::ServerMessage> out;
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (out.size() < count && std::chrono::steady_clock::now() < deadline) {
        connection.wait(20ms);
        for (auto& m : connection.poll()) {
            out.push_back(std::move(m));
        }
    }
    return out;
}

std::uint16_t closed_port() {
    asio::io_context ioc;
    tcp::acceptor acceptor(ioc, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
    return acceptor.local_endpoint().port(); // closed again when acceptor goes
}

TEST(Connection, MalformedUrlGivesAClosedConnectionWithTheReason) {
    auto connection = Connection::open("http://127.0.0.1:1");
    const auto status = connection->status();
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_NE(status.detail.find("must start with ws://"), std::string::npos);
    connection->send(proto::Ping{1}); // harmless
    EXPECT_TRUE(connection->poll().empty());
    EXPECT_FALSE(connection->wait(10ms));
}

TEST(Connection, RefusedConnectionSaysSoInPlainWords) {
    const auto port = closed_port();
    auto connection = Connection::open("ws://127.0.0.1:" + std::to_string(port));
    const auto status = wait_closed(*connection, 5s);
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_EQ(status.detail,
              "Could not reach 127.0.0.1:" + std::to_string(port) + ": connection refused.");
}

TEST(Connection, UnknownHostSaysSo) {
    auto connection = Connection::open("ws://no-such-host.invalid:7777");
    const auto status = wait_closed(*connection, 10s);
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_NE(status.detail.find("Could not find the server host 'no-such-host.invalid'"),
              std::string::npos)
        << status.detail;
}

TEST(Connection, ServerThatNeverAnswersTimesOut) {
    // Accepts the TCP connection but never answers the upgrade request.
    std::atomic<bool> release{false};
    OneShotServer server([&](tcp::socket&) {
        while (!release) {
            std::this_thread::sleep_for(5ms);
        }
    });
    ConnectionOptions options;
    options.connect_timeout = 300ms;
    const auto start = std::chrono::steady_clock::now();
    auto connection = Connection::open(server.url(), options);
    const auto status = wait_closed(*connection, 5s);
    const auto took = std::chrono::steady_clock::now() - start;
    release = true;
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_EQ(status.detail,
              "Could not reach " + server.url().substr(5) + ": no answer within 300 ms.");
    EXPECT_GE(took, 290ms);
    EXPECT_LT(took, 3s);
}

TEST(Connection, PlainHttpServerIsNotAWebSocketServer) {
    OneShotServer server([](tcp::socket& socket) {
        char request[1024];
        beast::error_code ec;
        socket.read_some(asio::buffer(request), ec);
        const std::string response =
            "HTTP/1.1 404 Not Found\r\nContent-Length: 0\r\nConnection: close\r\n\r\n";
        asio::write(socket, asio::buffer(response), ec);
    });
    auto connection = Connection::open(server.url());
    const auto status = wait_closed(*connection, 5s);
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_NE(status.detail.find("answered, but not as a WebSocket server"), std::string::npos)
        << status.detail;
}

TEST(Connection, MessagesQueuedWhileConnectingAreSentOnOpen) {
    OneShotServer server(websocket_peer(pong_server));
    auto connection = Connection::open(server.url());
    connection->send(proto::Ping{42});
    const auto messages = receive(*connection, 1);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(std::get<proto::Pong>(messages[0]), (proto::Pong{42, 5}));
    EXPECT_EQ(connection->status().state, ConnectionState::Open);
    EXPECT_EQ(connection->status().detail, "Connected to " + server.url().substr(5) + ".");
}

TEST(Connection, ManyMessagesArriveInOrder) {
    OneShotServer server(websocket_peer(pong_server));
    auto connection = Connection::open(server.url());
    constexpr int kCount = 200;
    for (int i = 0; i < kCount; ++i) {
        connection->send(proto::Ping{i});
    }
    const auto messages = receive(*connection, kCount);
    ASSERT_EQ(messages.size(), static_cast<std::size_t>(kCount));
    for (int i = 0; i < kCount; ++i) {
        EXPECT_EQ(std::get<proto::Pong>(messages[static_cast<std::size_t>(i)]).nonce, i);
    }
}

TEST(Connection, SendTextGoesOutUnchanged) {
    OneShotServer server(websocket_peer(pong_server));
    auto connection = Connection::open(server.url());
    connection->send_text(R"({"type":"ping","nonce":7,"extra":"ignored"})");
    const auto messages = receive(*connection, 1);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(std::get<proto::Pong>(messages[0]).nonce, 7);
}

TEST(Connection, SendsBeyondTheQueueBoundAreDropped) {
    // Sends made while connecting wait in the queue; with a bound of 1 the burst mostly falls
    // on a full queue. What gets through keeps its order and starts with the first.
    OneShotServer server(websocket_peer(pong_server));
    ConnectionOptions options;
    options.max_queued_sends = 1;
    auto connection = Connection::open(server.url(), options);
    for (int i = 0; i < 50; ++i) {
        connection->send(proto::Ping{i});
    }
    const auto messages = receive(*connection, 50, 1s);
    ASSERT_FALSE(messages.empty());
    EXPECT_LT(messages.size(), 50u);
    EXPECT_EQ(std::get<proto::Pong>(messages[0]).nonce, 0);
    for (std::size_t i = 1; i < messages.size(); ++i) {
        EXPECT_GT(std::get<proto::Pong>(messages[i]).nonce,
                  std::get<proto::Pong>(messages[i - 1]).nonce);
    }
}

TEST(Connection, FramesThatDoNotDecodeAreCountedAndSkipped) {
    OneShotServer server(websocket_peer([](Peer& ws) {
        beast::error_code ec;
        ws.text(true);
        ws.write(asio::buffer(std::string("not json")), ec);
        ws.write(asio::buffer(std::string(R"({"type":"warp"})")), ec);
        ws.binary(true);
        ws.write(asio::buffer(std::string(R"({"type":"pong","nonce":1,"server_time_ms":2})")), ec);
        ws.text(true);
        ws.write(asio::buffer(proto::encode(proto::Pong{3, 4})), ec);
        pong_server(ws);
    }));
    auto connection = Connection::open(server.url());
    const auto messages = receive(*connection, 1);
    ASSERT_EQ(messages.size(), 1u);
    EXPECT_EQ(std::get<proto::Pong>(messages[0]), (proto::Pong{3, 4}));
    EXPECT_EQ(connection->decode_errors(), 3);
}

TEST(Connection, ServerCloseCodeAndReasonAreReported) {
    OneShotServer server(websocket_peer([](Peer& ws) {
        beast::flat_buffer buffer;
        beast::error_code ec;
        ws.read(buffer, ec);
        ws.close(websocket::close_reason(websocket::close_code::policy_error, "rate"), ec);
        ws.read(buffer, ec); // until the client's close answer
    }));
    auto connection = Connection::open(server.url());
    connection->send(proto::Ping{1});
    const auto status = wait_closed(*connection, 5s);
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_EQ(status.detail, "The server closed the connection (code 1008: a server limit or "
                             "timeout was hit; it said 'rate').");
}

TEST(Connection, LostConnectionIsReported) {
    OneShotServer server(websocket_peer([](Peer& ws) {
        beast::flat_buffer buffer;
        beast::error_code ec;
        ws.read(buffer, ec);
        ws.next_layer().close(ec); // no close frame
    }));
    auto connection = Connection::open(server.url());
    connection->send(proto::Ping{1});
    const auto status = wait_closed(*connection, 5s);
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_NE(status.detail.find("The connection to " + server.url().substr(5) + " was lost"),
              std::string::npos)
        << status.detail;
}

TEST(Connection, SilentLinkIsTakenForLostAfterTheSilenceTimeout) {
    // The peer accepts, then reads nothing and sends nothing: it does not even answer the
    // connection's keep-alive ping, as on a link where no packet passes and no reset comes.
    std::atomic<bool> release{false};
    OneShotServer server(websocket_peer([&](Peer&) {
        while (!release) {
            std::this_thread::sleep_for(5ms);
        }
    }));
    ConnectionOptions options;
    options.silence_timeout = 600ms;
    auto connection = Connection::open(server.url(), options);
    const auto open_deadline = std::chrono::steady_clock::now() + 5s;
    while (connection->status().state == ConnectionState::Connecting &&
           std::chrono::steady_clock::now() < open_deadline) {
        connection->wait(10ms);
    }
    ASSERT_EQ(connection->status().state, ConnectionState::Open);
    const auto opened = std::chrono::steady_clock::now();
    const auto status = wait_closed(*connection, 5s);
    const auto took = std::chrono::steady_clock::now() - opened;
    release = true;
    EXPECT_EQ(status.state, ConnectionState::Closed);
    EXPECT_EQ(status.detail, "Nothing arrived from " + server.url().substr(5) +
                                 " for 600 ms: the link is silent, taken for lost.");
    EXPECT_EQ(status.close_code, 0);
    EXPECT_GE(took, 550ms);
    EXPECT_LT(took, 3s);
}

TEST(Connection, QuietPeerThatAnswersPingsStaysOpenPastTheSilenceTimeout) {
    // The peer sends no message at all but keeps reading, so it answers the connection's
    // keep-alive pings with pongs (Beast does): the link is alive, the connection stays open.
    OneShotServer server(websocket_peer(pong_server));
    ConnectionOptions options;
    options.silence_timeout = 300ms;
    auto connection = Connection::open(server.url(), options);
    const auto deadline = std::chrono::steady_clock::now() + 1500ms;
    while (std::chrono::steady_clock::now() < deadline) {
        connection->wait(20ms);
    }
    EXPECT_EQ(connection->status().state, ConnectionState::Open) << connection->status().detail;
    connection->close();
    EXPECT_EQ(wait_closed(*connection, 5s).detail, "Closed by this client.");
}

TEST(Connection, CloseSendsPendingMessagesThenACloseFrame) {
    std::atomic<int> pings{0};
    std::atomic<int> close_code{-1};
    OneShotServer server(websocket_peer([&](Peer& ws) {
        for (;;) {
            beast::flat_buffer buffer;
            beast::error_code ec;
            ws.read(buffer, ec);
            if (ec == websocket::error::closed) {
                close_code = ws.reason().code;
                return;
            }
            if (ec) {
                return;
            }
            ++pings;
        }
    }));
    auto connection = Connection::open(server.url());
    while (connection->status().state == ConnectionState::Connecting) {
        connection->wait(10ms);
    }
    for (int i = 0; i < 10; ++i) {
        connection->send(proto::Ping{i});
    }
    connection->close();
    EXPECT_EQ(connection->status().state, ConnectionState::Closed);
    EXPECT_EQ(connection->status().detail, "Closed by this client.");
    connection.reset(); // joins the I/O thread
    const auto deadline = std::chrono::steady_clock::now() + 2s;
    while (close_code.load() < 0 && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(5ms);
    }
    EXPECT_EQ(pings.load(), 10);
    EXPECT_EQ(close_code.load(), 1000);
}

TEST(Connection, SendAfterCloseIsDroppedAndCloseIsIdempotent) {
    OneShotServer server(websocket_peer(pong_server));
    auto connection = Connection::open(server.url());
    connection->close();
    connection->close();
    connection->send(proto::Ping{1});
    EXPECT_FALSE(connection->wait(50ms));
    EXPECT_EQ(connection->status().state, ConnectionState::Closed);
}

TEST(Connection, WaitReturnsAtOnceWhenAMessageIsWaiting) {
    OneShotServer server(websocket_peer(pong_server));
    auto connection = Connection::open(server.url());
    connection->send(proto::Ping{9});
    const auto deadline = std::chrono::steady_clock::now() + 5s;
    while (!connection->wait(20ms) && std::chrono::steady_clock::now() < deadline) {
    }
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(connection->wait(2s));
    EXPECT_LT(std::chrono::steady_clock::now() - start, 500ms);
}

} // namespace
} // namespace carrom::net
