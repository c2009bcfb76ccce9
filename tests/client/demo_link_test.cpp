#include "carrom/client/demo_link.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/proto/codec.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace carrom::client {
namespace {

struct DemoHarness {
    double now = 0.0;
    DemoConfig config = [] {
        DemoConfig c;
        c.first_shot_at_s = 0.5;
        c.autoplay_after_s = 0.5;
        return c;
    }();
    DemoLink link{PhysicsConfig{}, [this] { return now; }, config};
};

TEST(DemoLink, SpeaksTheProtocol) {
    DemoHarness h;
    EXPECT_EQ(h.link.status().state, LinkState::Open);
    h.link.send(proto::Hello{proto::kProtocolVersion, "Ana", std::nullopt});
    h.link.send(proto::CreateRoom{});
    auto first = h.link.poll();
    ASSERT_EQ(first.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<proto::Welcome>(first[0]));
    ASSERT_TRUE(std::holds_alternative<proto::RoomState>(first[1]));
    EXPECT_EQ(std::get<proto::RoomState>(first[1]).seats[0].name, "Ana");
    EXPECT_EQ(std::get<proto::RoomState>(first[1]).to_play, 1); // the demo opponent breaks
    // Every message the demo sends survives the real codec, so it is valid protocol.
    int snapshots = 0;
    int results = 0;
    std::int64_t last_seq = 0;
    for (int frame = 0; frame < 60 * 40 && results < 2; ++frame) {
        h.now = frame / 60.0;
        for (const proto::ServerMessage& m : h.link.poll()) {
            const auto decoded = proto::decode_server(proto::encode(m));
            ASSERT_TRUE(decoded.ok()) << decoded.error.code << ": " << decoded.error.message;
            if (const auto* s = std::get_if<proto::Snapshot>(&m)) {
                EXPECT_GT(s->seq, last_seq);
                last_seq = s->seq;
                ++snapshots;
            }
            results += std::holds_alternative<proto::ShotResult>(m) ? 1 : 0;
        }
    }
    EXPECT_EQ(results, 2); // the break, then our autoplayed shot
    EXPECT_GT(snapshots, 60);
}

TEST(DemoLink, RejectsShotsOutOfTurn) {
    DemoHarness h;
    h.config.first_shot_at_s = 100.0;
    DemoLink link{PhysicsConfig{}, [&h] { return h.now; }, h.config};
    link.send(proto::Hello{});
    link.send(proto::CreateRoom{});
    link.poll();
    link.send(proto::Shoot{0, 300.0, -1.57, 20.0});
    const auto out = link.poll();
    ASSERT_EQ(out.size(), 1u);
    ASSERT_TRUE(std::holds_alternative<proto::Error>(out[0]));
    EXPECT_EQ(std::get<proto::Error>(out[0]).code, "not_your_turn");
}

TEST(DemoLink, FeedsTheMatchModelToTheEndOfTheBreak) {
    DemoHarness h;
    MatchModel model{PhysicsConfig{}};
    h.link.send(proto::Hello{});
    h.link.send(proto::CreateRoom{});
    bool saw_moving = false;
    for (int frame = 0; frame < 60 * 20; ++frame) {
        h.now = frame / 60.0;
        for (const proto::ServerMessage& m : h.link.poll()) {
            model.handle(m, h.now);
        }
        const auto bodies = model.render(h.now);
        for (const RenderedBody& b : bodies) {
            ASSERT_TRUE(std::isfinite(b.pos_px.x) && std::isfinite(b.pos_px.y));
        }
        saw_moving = saw_moving || model.view().phase == proto::Phase::Moving;
    }
    EXPECT_TRUE(saw_moving);
    EXPECT_GE(model.view().turn, 1);
}

TEST(DemoLink, LeaveClosesTheLink) {
    DemoHarness h;
    h.link.send(proto::Leave{});
    EXPECT_EQ(h.link.status().state, LinkState::Closed);
    EXPECT_TRUE(h.link.poll().empty());
}

} // namespace
} // namespace carrom::client
