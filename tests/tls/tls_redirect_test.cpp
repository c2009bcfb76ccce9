// carrom-bot on a wss:// address follows a cluster's `redirect` (docs/protocol.md, "Redirects")
// to wss:// only: a TLS front of this test (Beast, the test PKI's server certificate) answers
// every room request with `redirect` and close 4005. To a real carrom-server over TLS the bot
// follows and creates its room there; to ws:// on the same host (a listener that counts
// connections) it never connects and fails with `redirect refused: ...`.
#include "tls_test_support.hpp"

#include "support/tcp_listener.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/proto/error.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/asio/ssl/stream.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/ssl.hpp>
#include <boost/beast/websocket/stream.hpp>
#include <gtest/gtest.h>

namespace carrom::tls_test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

using test_support::TcpListener;

// Over TLS: welcome, then `redirect` (room, no code) to `target` for the room request; close 4005.
void serve_tls_redirect(const Pki& pki, const std::string& target, tcp::socket& socket) {
    asio::ssl::context context(asio::ssl::context::tls_server);
    context.use_certificate_chain_file(pki.file("server.pem"));
    context.use_private_key_file(pki.file("server.key"), asio::ssl::context::pem);
    websocket::stream<asio::ssl::stream<tcp::socket>> ws(std::move(socket), context);
    beast::error_code ec;
    ws.next_layer().handshake(asio::ssl::stream_base::server, ec);
    if (!ec) {
        ws.accept(ec);
    }
    beast::flat_buffer buffer;
    if (!ec) {
        ws.read(buffer, ec); // hello
    }
    if (ec) {
        return;
    }
    ws.text(true);
    ws.write(asio::buffer(proto::encode(
                 proto::Welcome{proto::kProtocolVersion, 7, std::string(32, 'e'), 1})),
             ec);
    ws.read(buffer, ec); // the room request
    ws.write(asio::buffer(proto::encode(proto::Redirect{target, "room", "", proto::Role::Player})),
             ec);
    ws.close(websocket::close_reason(static_cast<std::uint16_t>(proto::kCloseRedirected)), ec);
}

TEST(TlsRedirect, BotOnWssFollowsToWssAndNeverToWs) {
    const Pki pki;
    ASSERT_TRUE(pki.made());
    pki.make_live("server");
    const auto server = start_tls_server(pki, {"--shot-clock", "0", "--log-level", "warn"});
    ASSERT_TRUE(server->start()) << server->log();
    const std::string real = "wss://127.0.0.1:" + std::to_string(server->port()) + "/";
    TcpListener to_real("127.0.0.1",
                        [&](tcp::socket& socket) { serve_tls_redirect(pki, real, socket); });
    // --create waits for an opponent: 2 s, then it stops with the room it made there.
    test_support::ChildProcess creator(
        {CARROM_BOT_PATH, "--url", "wss://127.0.0.1:" + std::to_string(to_real.port()), "--ca-file",
         pki.file("ca.pem"), "--create", "--timeout", "2"});
    const BotRun followed = finish_bot(creator);
    ASSERT_TRUE(followed.summary.is_object()) << followed.output;
    EXPECT_EQ(followed.summary["redirects"], 1) << followed.output;
    EXPECT_EQ(followed.summary["room"].get<std::string>().size(), 6u) << followed.output;

    TcpListener plain; // ws:// on the same host
    const std::string downgrade = "ws://127.0.0.1:" + std::to_string(plain.port()) + "/";
    TcpListener to_plain("127.0.0.1",
                         [&](tcp::socket& socket) { serve_tls_redirect(pki, downgrade, socket); });
    const std::string front = "wss://127.0.0.1:" + std::to_string(to_plain.port());
    const BotRun refused = run_bot(front, {"--ca-file", pki.file("ca.pem"), "--create"});
    ASSERT_TRUE(refused.summary.is_object()) << refused.output;
    EXPECT_NE(refused.exit, 0);
    EXPECT_EQ(refused.summary["failure"], "redirect refused: " + downgrade +
                                              " is not an address of this cluster (" + front + ").")
        << refused.output;
    EXPECT_EQ(refused.summary["redirects"], 0);
    EXPECT_EQ(plain.accepted(), 0);
}

} // namespace
} // namespace carrom::tls_test
