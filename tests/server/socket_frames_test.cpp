// Frames the server will not read: oversized, binary and invalid UTF-8 text frames each end the
// connection with their close code (docs/protocol.md), and the others go on.
#include "server/socket_fixture.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::server {
namespace {

using testing::SocketTest;
using testing::test_settings;
using testing::WsTestClient;

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

} // namespace
} // namespace carrom::server
