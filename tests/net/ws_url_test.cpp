#include "carrom/net/ws_url.hpp"

#include <gtest/gtest.h>

namespace carrom::net {
namespace {

WsUrl parsed(std::string_view text) {
    auto result = parse_ws_url(text);
    EXPECT_TRUE(std::holds_alternative<WsUrl>(result)) << text;
    return std::holds_alternative<WsUrl>(result) ? std::get<WsUrl>(result) : WsUrl{};
}

std::string error_of(std::string_view text) {
    auto result = parse_ws_url(text);
    EXPECT_TRUE(std::holds_alternative<std::string>(result)) << text;
    return std::holds_alternative<std::string>(result) ? std::get<std::string>(result) : "";
}

TEST(WsUrl, HostPortAndDefaultTarget) {
    const WsUrl url = parsed("ws://127.0.0.1:7777");
    EXPECT_EQ(url.host, "127.0.0.1");
    EXPECT_EQ(url.port, 7777);
    EXPECT_EQ(url.target, "/");
    EXPECT_EQ(url.authority(), "127.0.0.1:7777");
    EXPECT_FALSE(url.tls);
}

TEST(WsUrl, WssIsTls) {
    const WsUrl url = parsed("wss://play.example.org:443/carrom");
    EXPECT_TRUE(url.tls);
    EXPECT_EQ(url.host, "play.example.org");
    EXPECT_EQ(url.port, 443);
    EXPECT_EQ(url.target, "/carrom");
    EXPECT_TRUE(parsed("wss://[::1]:7777").tls);
    EXPECT_EQ(error_of("wss://h"),
              "The server address 'wss://h' needs a port, as in ws://127.0.0.1:7777.");
}

TEST(WsUrl, PathAndQueryAreKept) {
    EXPECT_EQ(parsed("ws://example.org:80/play/room").target, "/play/room");
    EXPECT_EQ(parsed("ws://example.org:80?x=1").target, "/?x=1");
}

TEST(WsUrl, BracketedIpv6) {
    const WsUrl url = parsed("ws://[::1]:9000/");
    EXPECT_EQ(url.host, "::1");
    EXPECT_EQ(url.port, 9000);
    EXPECT_EQ(url.authority(), "[::1]:9000");
}

TEST(WsUrl, PortBounds) {
    EXPECT_EQ(parsed("ws://h:1").port, 1);
    EXPECT_EQ(parsed("ws://h:65535").port, 65535);
    EXPECT_NE(error_of("ws://h:0").find("port"), std::string::npos);
    EXPECT_NE(error_of("ws://h:65536").find("port"), std::string::npos);
    EXPECT_NE(error_of("ws://h:-1").find("port"), std::string::npos);
    EXPECT_NE(error_of("ws://h:12a").find("port"), std::string::npos);
    EXPECT_NE(error_of("ws://h:").find("port"), std::string::npos);
}

TEST(WsUrl, ErrorsSayWhatIsWrong) {
    EXPECT_EQ(error_of("http://h:80"),
              "The server address 'http://h:80' must start with ws:// or wss:// (for example "
              "ws://127.0.0.1:7777).");
    EXPECT_EQ(error_of("ws://h"),
              "The server address 'ws://h' needs a port, as in ws://127.0.0.1:7777.");
    EXPECT_EQ(error_of("ws://:80"), "The server address 'ws://:80' has no host name.");
    EXPECT_NE(error_of("ws://::1:80").find("brackets"), std::string::npos);
    EXPECT_NE(error_of("ws://[::1:80").find("closing ]"), std::string::npos);
    EXPECT_NE(error_of("ws://h:80/#x").find("fragment"), std::string::npos);
    EXPECT_NE(error_of("ws://h:80/a b").find("path"), std::string::npos);
    EXPECT_NE(error_of("").find("must start with ws://"), std::string::npos);
    EXPECT_NE(error_of("ws:/h:443").find("must start with ws://"), std::string::npos);
}

TEST(WsUrl, ControlCharactersAreNotEchoed) {
    const std::string error = error_of(std::string("ws://h\x01x:80"));
    EXPECT_EQ(error.find('\x01'), std::string::npos);
    EXPECT_NE(error.find("character"), std::string::npos);
}

TEST(WsUrl, LongInputIsShortenedInTheMessage) {
    const std::string error = error_of(std::string(5000, 'a'));
    EXPECT_LT(error.size(), 200u);
    EXPECT_NE(error.find("...'"), std::string::npos);
}

} // namespace
} // namespace carrom::net
