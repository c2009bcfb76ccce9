// What the window says while the connection is lost, and once the session gives up.
#include "carrom/client/reconnect_text.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

TEST(ReconnectText, WaitingForTheNextTry) {
    ReconnectInfo info;
    info.attempt = 2;
    info.next_try_in_s = 0.93;
    info.gives_up_in_s = 58.2;
    info.reason = "The server closed the connection (code 1012: the server is restarting).";
    const ReconnectText text = reconnect_text(SessionPhase::Reconnecting, info, "");
    EXPECT_EQ(text.title, "Reconnecting...");
    ASSERT_EQ(text.lines.size(), 3u);
    EXPECT_EQ(text.lines[0], "Attempt 2, next try in 1.0 s.");
    EXPECT_EQ(text.lines[1], info.reason);
    EXPECT_EQ(text.lines[2], "Your seat is held; giving up in 59 s.");
}

TEST(ReconnectText, WhileATryConnects) {
    ReconnectInfo info;
    info.attempt = 3;
    info.trying = true;
    info.gives_up_in_s = 4.01;
    const ReconnectText text = reconnect_text(SessionPhase::Greeting, info, "");
    ASSERT_EQ(text.lines.size(), 2u);
    EXPECT_EQ(text.lines[0], "Attempt 3: connecting.");
    EXPECT_EQ(text.lines[1], "Your seat is held; giving up in 4.1 s.");
}

TEST(ReconnectText, GaveUpSaysConnectionLostWithTheReason) {
    ReconnectInfo info;
    info.attempt = 17;
    info.reason = "Could not reach 127.0.0.1:7777: connection refused.";
    const ReconnectText text = reconnect_text(SessionPhase::Failed, info, "ignored");
    EXPECT_EQ(text.title, "Disconnected");
    ASSERT_EQ(text.lines.size(), 2u);
    EXPECT_EQ(text.lines[0],
              "Connection lost: Could not reach 127.0.0.1:7777: connection refused.");
    EXPECT_EQ(text.lines[1], "Gave up after 17 tries.");
}

} // namespace
} // namespace carrom::client
