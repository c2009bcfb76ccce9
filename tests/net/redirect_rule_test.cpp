// net::redirect_allowed and ws_url_host: which redirect URLs a client follows (docs/protocol.md,
// "Redirects"); the golden session cases check the same through net::SessionCore and its web
// port.
#include "carrom/net/redirect_rule.hpp"

#include <gtest/gtest.h>

namespace carrom::net {
namespace {

TEST(RedirectRule, HostIsLowercasedWithoutPortOrPath) {
    EXPECT_EQ(ws_url_host("ws://127.0.0.1:7777"), "127.0.0.1");
    EXPECT_EQ(ws_url_host("wss://Carrom.Example/i/b/"), "carrom.example");
    EXPECT_EQ(ws_url_host("ws://carrom.example?x=1"), "carrom.example");
    EXPECT_EQ(ws_url_host("ws://[::1]:7801/"), "[::1]");
}

TEST(RedirectRule, NoHostForOtherSchemesUserInformationOrBlanks) {
    for (const char* url : {"http://127.0.0.1:7777/", "WS://h:1/", "ws:/h:1/", "ws://:7801/",
                            "ws://u@h:1/", "ws://h:1/a b", "ws://[]:1/", "ws://[::1:1/", ""}) {
        EXPECT_EQ(ws_url_host(url), "") << url;
    }
}

TEST(RedirectRule, FollowsOnlyToTheGivenHost) {
    const char* address = "ws://127.0.0.1:7777";
    EXPECT_TRUE(redirect_allowed(address, address, "ws://127.0.0.1:7801/i/b/"));
    EXPECT_TRUE(redirect_allowed(address, address, "wss://127.0.0.1:7802/"));
    EXPECT_FALSE(redirect_allowed(address, address, "ws://127.0.0.2:7777/"));
    EXPECT_FALSE(redirect_allowed(address, address, "ws://127.0.0.1.evil:7777/"));
    EXPECT_FALSE(redirect_allowed(address, address, "ws://127.0.0.1@evil:7777/"));
    EXPECT_FALSE(redirect_allowed(address, "", "ws://127.0.0.1:7801/"));
}

TEST(RedirectRule, NeverFromWssToWs) {
    const char* address = "wss://carrom.example:443";
    EXPECT_FALSE(redirect_allowed(address, address, "ws://carrom.example:80/i/b/"));
    EXPECT_TRUE(redirect_allowed(address, address, "wss://carrom.example/i/b/"));
    // The link that got the redirect counts, not the address: ws:// there may go to wss://.
    EXPECT_TRUE(redirect_allowed("ws://carrom.example:80", address, "ws://carrom.example/"));
}

} // namespace
} // namespace carrom::net
