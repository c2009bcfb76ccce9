#include "carrom/client/demo_link.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/proto/codec.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

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
    // As from a server: welcome; the room with the player alone and the board; the room with
    // both seats taken; the first turn, the opponent's break.
    auto first = h.link.poll();
    ASSERT_EQ(first.size(), 5u);
    EXPECT_TRUE(std::holds_alternative<proto::Welcome>(first[0]));
    ASSERT_TRUE(std::holds_alternative<proto::RoomState>(first[1]));
    EXPECT_EQ(std::get<proto::RoomState>(first[1]).phase, proto::Phase::Waiting);
    ASSERT_TRUE(std::holds_alternative<proto::Snapshot>(first[2]));
    EXPECT_TRUE(std::get<proto::Snapshot>(first[2]).keyframe);
    ASSERT_TRUE(std::holds_alternative<proto::RoomState>(first[3]));
    const auto& room = std::get<proto::RoomState>(first[3]);
    EXPECT_EQ(room.you, 0);
    EXPECT_EQ(room.seats[0].name, "Ana");
    EXPECT_TRUE(room.seats[1].bot);
    EXPECT_EQ(room.to_play, 1); // the demo opponent breaks
    ASSERT_TRUE(std::holds_alternative<proto::Event>(first[4]));
    EXPECT_EQ(std::get<proto::TurnEvent>(std::get<proto::Event>(first[4])).seat, 1);
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

// The demo plays the server's own room: snapshot values are quantised to 0.01 as on the wire,
// shot results carry one score per seat, and a player who lets the shot clock run out three
// times loses with the reason "clock".
TEST(DemoLink, PlaysTheServersRoom) {
    DemoHarness h;
    h.config.first_shot_at_s = 0.1;
    h.config.opponent_think_s = 0.1;
    h.config.shot_clock_s = 1.0;
    h.config.autoplay_after_s = -1.0; // the player never shoots
    DemoLink link{PhysicsConfig{}, [&h] { return h.now; }, h.config};
    link.send(proto::Hello{proto::kProtocolVersion, "Ana", std::nullopt});
    link.send(proto::CreateRoom{});
    std::optional<proto::GameEndEvent> end;
    int results = 0;
    int deltas = 0;
    for (int frame = 0; frame < 60 * 600 && !end; ++frame) {
        h.now = frame / 60.0;
        for (const proto::ServerMessage& m : link.poll()) {
            if (const auto* s = std::get_if<proto::Snapshot>(&m)) {
                // Deltas are rounded to 0.01; keyframes of a board at rest are exact.
                const std::vector<proto::SnapshotBody> none;
                for (const proto::SnapshotBody& b : s->keyframe ? none : s->bodies) {
                    for (const double v : {b.pos_px.x, b.pos_px.y, b.vel_px_s.x, b.vel_px_s.y}) {
                        ASSERT_EQ(v, proto::quantise(v));
                    }
                }
                deltas += s->keyframe ? 0 : 1;
            } else if (const auto* r = std::get_if<proto::ShotResult>(&m)) {
                EXPECT_EQ(r->scores.size(), 2u);
                EXPECT_EQ(r->points.size(), 2u);
                ++results;
            } else if (const auto* e = std::get_if<proto::Event>(&m)) {
                if (const auto* g = std::get_if<proto::GameEndEvent>(e)) {
                    end = *g;
                }
            }
        }
    }
    ASSERT_TRUE(end.has_value());
    EXPECT_EQ(end->reason, "clock");
    EXPECT_EQ(end->winner, 1);
    EXPECT_GE(results, 4); // the opponent's strokes and the player's three expiries
    EXPECT_GT(deltas, 0);
}

TEST(DemoLink, LeaveClosesTheLink) {
    DemoHarness h;
    h.link.send(proto::Leave{});
    EXPECT_EQ(h.link.status().state, LinkState::Closed);
    EXPECT_TRUE(h.link.poll().empty());
}

} // namespace
} // namespace carrom::client
