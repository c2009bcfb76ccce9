// tests/golden/session/*.json replayed against net::SessionCore: each event gives the actions and
// the state the file records (tests/web/session_test.mjs replays the same files against the web
// client's port, web/js/session_core.js).
#include "session_golden.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace carrom::net {
namespace {

using nlohmann::json;

std::filesystem::path golden_dir() {
    const char* source = std::getenv("CARROM_SOURCE_DIR");
    return std::filesystem::path(source != nullptr ? source : ".") / "tests/golden/session";
}

// Equal, numbers within 1e-9 (seconds).
bool same(const json& a, const json& b) {
    if (a.is_number() && b.is_number()) {
        return std::abs(a.get<double>() - b.get<double>()) <= 1e-9;
    }
    if (a.type() != b.type() || a.size() != b.size()) {
        return false;
    }
    if (a.is_array()) {
        for (std::size_t i = 0; i < a.size(); ++i) {
            if (!same(a[i], b[i])) {
                return false;
            }
        }
        return true;
    }
    if (a.is_object()) {
        for (auto it = a.begin(); it != a.end(); ++it) {
            if (!b.contains(it.key()) || !same(it.value(), b.at(it.key()))) {
                return false;
            }
        }
        return true;
    }
    return a == b;
}

TEST(SessionGolden, EveryCaseReplaysAsRecorded) {
    int cases = 0;
    for (const auto& entry : std::filesystem::directory_iterator(golden_dir())) {
        if (entry.path().extension() != ".json") {
            continue;
        }
        ++cases;
        std::ifstream in(entry.path());
        const json golden = json::parse(in);
        SessionCore core = golden::core_for(golden);
        int index = 0;
        for (const json& step : golden.at("steps")) {
            const json answer = golden::play(core, step);
            const json expected{{"actions", step.at("actions")}, {"state", step.at("state")}};
            ASSERT_TRUE(same(answer, expected))
                << entry.path().filename() << " step " << index << " (" << step.at("event")
                << " at " << step.at("t") << "): got " << answer.dump() << ", recorded "
                << expected.dump();
            ++index;
        }
    }
    EXPECT_GE(cases, 20) << golden_dir();
}

TEST(SessionCore, TheWaitIsReadableAsTimes) {
    SessionCore core;
    core.request();
    core.start("");
    core.link_opened();
    core.welcome("t");
    core.room_state();
    EXPECT_FALSE(core.drops_room_messages());
    const SessionActions wait = core.link_closed(100.0, 1006, 0.5);
    ASSERT_EQ(wait.size(), 1u);
    EXPECT_EQ(wait[0].kind, SessionActionKind::Wait);
    EXPECT_DOUBLE_EQ(wait[0].wait_s, 0.375); // d = 0.5 s, 3/4 of the way in [d/2, d]
    EXPECT_DOUBLE_EQ(core.retry_at_s(), 100.375);
    EXPECT_DOUBLE_EQ(core.lost_since_s(), 100.0);
    EXPECT_DOUBLE_EQ(core.gives_up_at_s(), 230.0);
    EXPECT_TRUE(core.tick(100.374).empty());
    EXPECT_EQ(core.tick(100.375), (SessionActions{{SessionActionKind::Connect}}));
}

TEST(SessionCore, RoomMessagesInTheLobbyAreDropped) {
    SessionCore core;
    core.request();
    core.start("");
    core.link_opened();
    core.welcome("t");
    EXPECT_FALSE(core.drops_room_messages()); // joining
    core.room_state();
    EXPECT_FALSE(core.drops_room_messages());
    EXPECT_EQ(core.leave(), (SessionActions{{SessionActionKind::SendLeave}}));
    EXPECT_TRUE(core.drops_room_messages());
}

TEST(SessionCore, RefusedRedirectsSaySoInOneSentence) {
    SessionCore core({}, ReconnectPolicy::Always, "ws://127.0.0.1:7777");
    core.start("");
    core.link_opened();
    core.welcome("t");
    const proto::Redirect away{"ws://10.0.0.9:7777/\x01", "room", "", proto::Role::Player};
    EXPECT_EQ(core.redirect(away),
              (SessionActions{{SessionActionKind::GiveUp, 0.0, GiveUpReason::RedirectRefused}}));
    EXPECT_EQ(core.refused_redirect(), "redirect refused: ws://10.0.0.9:7777/? is not an address "
                                       "of this cluster (ws://127.0.0.1:7777).");
    core.start("");
    const proto::Redirect near{"ws://127.0.0.1:7801/", "room", "K7M2QX", proto::Role::Player};
    for (int i = 0; i < SessionCore::kMaxRedirects; ++i) {
        core.link_opened();
        core.welcome("t");
        EXPECT_EQ(core.redirect(near), (SessionActions{{SessionActionKind::Connect}}));
    }
    core.link_opened();
    core.welcome("t");
    EXPECT_EQ(core.redirect(near).front().reason, GiveUpReason::RedirectRefused);
    EXPECT_EQ(
        core.refused_redirect(),
        "redirect refused: more than 3 redirects in a row, the last to ws://127.0.0.1:7801/.");
}

} // namespace
} // namespace carrom::net
