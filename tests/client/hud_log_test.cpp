#include "carrom/client/hud_log.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

std::vector<std::string> shown(const HudLog& log, double local_s) {
    std::vector<std::string> out;
    for (const HudLine& l : log.visible(local_s)) {
        out.push_back(l.text);
    }
    return out;
}

TEST(HudLog, ALineStillShownIsNotShownTwice) {
    HudLog log(5, 6.0);
    log.post("Your turn", Tone::Info, 0.0);
    log.post("Asha pocketed 1 white coin", Tone::Good, 1.0);
    log.post("Your turn", Tone::Info, 2.0);
    EXPECT_EQ(shown(log, 2.0),
              (std::vector<std::string>{"Asha pocketed 1 white coin", "Your turn"}));
    // The newest copy keeps its own time: still shown 6 s after the second post.
    EXPECT_EQ(shown(log, 8.0), (std::vector<std::string>{"Your turn"}));
}

TEST(HudLog, ALineNoLongerShownMayComeAgain) {
    HudLog log(5, 6.0);
    log.post("Your turn", Tone::Info, 0.0);
    log.post("Your turn", Tone::Info, 7.0);
    EXPECT_EQ(log.all().size(), 2U);
    EXPECT_EQ(shown(log, 7.0), (std::vector<std::string>{"Your turn"}));
}

TEST(HudLog, KeepsAtMostItsCapacity) {
    HudLog log(2, 6.0);
    log.post("a", Tone::Info, 0.0);
    log.post("b", Tone::Info, 0.0);
    log.post("c", Tone::Info, 0.0);
    EXPECT_EQ(shown(log, 0.0), (std::vector<std::string>{"b", "c"}));
}

} // namespace
} // namespace carrom::client
