// A shot as the room streams it: deltas at the snapshot rate, then the final keyframe and the
// result, each with its delivery kind; keyframes for slow peers and late spectators, seq always
// rising, and spectators' comings and goings sent to nobody else.
#include "room/room_fixture.hpp"

#include "carrom/proto/codec.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <variant>

namespace carrom::room {
namespace {

using testing::FakePeer;
using testing::RoomTest;

TEST_F(RoomTest, ShotStreamsSnapshotsThenTheResult) {
    seat_both();
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    a_->clear();
    watcher_->clear();
    room_.shoot(*a_, break_shot(0));
    EXPECT_TRUE(a_->error_codes().empty());
    EXPECT_EQ(room_.phase(), proto::Phase::Moving);
    const int ticks = play_out();
    EXPECT_GT(ticks, 30); // a break moves for more than half a second at 60 Hz
    const auto snaps = a_->all<proto::Snapshot>();
    ASSERT_GE(snaps.size(), 2U);
    // Sequence numbers rise by one; times rise; only the last one is a keyframe.
    for (std::size_t i = 1; i < snaps.size(); ++i) {
        EXPECT_EQ(snaps[i].seq, snaps[i - 1].seq + 1);
        EXPECT_GE(snaps[i].t_s, snaps[i - 1].t_s);
    }
    EXPECT_FALSE(snaps.front().keyframe);
    EXPECT_TRUE(snaps.back().keyframe);
    // The first delta carries only the striker, moving up at 25 * 60 px/s.
    ASSERT_EQ(snaps.front().bodies.size(), 1U);
    EXPECT_EQ(snaps.front().bodies[0].id, kStrikerId);
    EXPECT_NEAR(snaps.front().bodies[0].vel_px_s.y, -1500.0, 0.01);
    // Deltas are at the snapshot rate: consecutive non-final ones 1/60 s apart.
    EXPECT_NEAR(snaps[2].t_s - snaps[1].t_s, 1.0 / 60.0, 0.002);
    const auto results = a_->all<proto::ShotResult>();
    ASSERT_EQ(results.size(), 1U);
    EXPECT_EQ(results[0].turn, 0);
    EXPECT_EQ(results[0].seat, 0);
    EXPECT_EQ(results[0].next_turn, 1);
    // Collisions were reported for sound, and the spectator saw exactly the same stream.
    EXPECT_FALSE(a_->events<proto::CollisionEvent>().empty());
    EXPECT_EQ(watcher_->all<proto::Snapshot>(), snaps);
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    EXPECT_EQ(a_->last_room_state().turn, 1);
    EXPECT_EQ(counters_.shots_total.load(), 1);
}

// What the write queue may drop under back-pressure: deltas (a keyframe repairs them) and the
// collision and cushion cues (sound only); never a pocket, the result or anything else.
TEST_F(RoomTest, ShotMessagesCarryTheirDeliveryKinds) {
    seat_both();
    a_->clear();
    room_.shoot(*a_, break_shot(0));
    play_out();
    ASSERT_EQ(a_->received.size(), a_->kinds.size());
    int cues = 0;
    for (std::size_t i = 0; i < a_->received.size(); ++i) {
        const auto& message = a_->received[i];
        MessageKind expected = MessageKind::Normal;
        if (const auto* snapshot = std::get_if<proto::Snapshot>(&message)) {
            expected = snapshot->keyframe ? MessageKind::Normal : MessageKind::Snapshot;
        } else if (const auto* event = std::get_if<proto::Event>(&message)) {
            const bool cue = std::holds_alternative<proto::CollisionEvent>(*event) ||
                             std::holds_alternative<proto::CushionEvent>(*event);
            expected = cue ? MessageKind::Cue : MessageKind::Normal;
            cues += cue ? 1 : 0;
        } else if (std::holds_alternative<proto::RoomState>(message)) {
            expected = MessageKind::State; // a newer one supersedes it
        }
        EXPECT_EQ(a_->kinds[i], expected) << "message " << i;
    }
    EXPECT_GT(cues, 10); // a break's collisions
}

TEST_F(RoomTest, DeltasReconstructTheFinalKeyframeBeforeTheRulesAct) {
    seat_both();
    a_->clear();
    room_.shoot(*a_, break_shot(0));
    play_out();
    // Apply every delta to the initial board; pieces the rules did not move must match the final
    // keyframe.
    std::map<int, proto::SnapshotBody> board;
    const auto snaps = a_->all<proto::Snapshot>();
    std::set<int> pocketed;
    for (const auto& s : snaps) {
        if (s.keyframe) {
            break;
        }
        for (const auto& b : s.bodies) {
            board[b.id] = b;
        }
        for (int id : s.pocketed) {
            pocketed.insert(id);
        }
    }
    const auto& final_frame = snaps.back();
    const auto result = a_->all<proto::ShotResult>().back();
    const std::set<int> returned(result.returned.begin(), result.returned.end());
    for (const auto& b : final_frame.bodies) {
        if (b.id == kStrikerId || returned.count(b.id) != 0 || board.count(b.id) == 0) {
            continue;
        }
        // The deltas carry values rounded to 0.01 px, the keyframe of the board at rest the
        // exact ones: they agree to that rounding.
        const Vec2 rounded{proto::quantise(b.pos_px.x), proto::quantise(b.pos_px.y)};
        EXPECT_EQ(board[b.id].pos_px, rounded) << "body " << b.id;
        EXPECT_EQ(board[b.id].vel_px_s, (Vec2{0.0, 0.0})) << "body " << b.id;
    }
    for (int id : pocketed) {
        if (id != kStrikerId && returned.count(id) == 0) {
            EXPECT_NE(std::find(final_frame.pocketed.begin(), final_frame.pocketed.end(), id),
                      final_frame.pocketed.end());
        }
    }
}

TEST_F(RoomTest, SlowPeerGetsAKeyframeInsteadOfADelta) {
    seat_both();
    room_.shoot(*a_, break_shot(0));
    b_->clear();
    b_->wants_keyframe = true;
    clock_.advance_ms(17);
    room_.tick();
    const auto snaps = b_->all<proto::Snapshot>();
    ASSERT_EQ(snaps.size(), 1U);
    EXPECT_TRUE(snaps[0].keyframe);
    EXPECT_EQ(snaps[0].bodies.size() + snaps[0].pocketed.size(), 20U);
    play_out();
}

// Every snapshot a connection receives has a larger seq than the one before: across a shot,
// its final keyframe and a rematch's new board; a spectator who joins mid-shot gets a keyframe
// carrying the seq of the last delta (the state it equals), then the deltas after it.
TEST_F(RoomTest, SeqRisesOnEveryConnectionAcrossAShotAndARematch) {
    const auto rising = [](const FakePeer& peer) {
        const auto snaps = peer.all<proto::Snapshot>();
        for (std::size_t i = 1; i < snaps.size(); ++i) {
            if (snaps[i].seq <= snaps[i - 1].seq) {
                return false;
            }
        }
        return !snaps.empty();
    };
    seat_both();
    room_.shoot(*a_, break_shot(0));
    clock_.advance_ms(100);
    room_.tick();
    const std::int64_t before_join = room_.seq();
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    const auto joined = watcher_->all<proto::Snapshot>();
    ASSERT_EQ(joined.size(), 1U);
    EXPECT_TRUE(joined[0].keyframe);
    EXPECT_EQ(joined[0].seq, before_join);
    play_out();
    const auto after_join = watcher_->all<proto::Snapshot>();
    ASSERT_GT(after_join.size(), 1U);
    EXPECT_EQ(after_join[1].seq, before_join + 1);

    room_.disconnected(*b_);
    clock_.advance_ms(60000);
    room_.tick(); // b forfeits: game over
    ASSERT_EQ(room_.phase(), proto::Phase::GameOver);
    auto c = std::make_shared<FakePeer>(5, "Cal");
    ASSERT_FALSE(room_.join(c, proto::Role::Player));
    const std::int64_t final_seq = a_->all<proto::Snapshot>().back().seq;
    room_.rematch(*a_);
    room_.rematch(*c);
    ASSERT_EQ(room_.phase(), proto::Phase::Aiming);
    const auto rematch = a_->all<proto::Snapshot>().back();
    EXPECT_TRUE(rematch.keyframe);
    EXPECT_GT(rematch.seq, final_seq);
    EXPECT_TRUE(rising(*a_));
    EXPECT_TRUE(rising(*watcher_));
    EXPECT_TRUE(rising(*c));
}

// Spectators coming and going send the others nothing (no room_state of about 3 KB each time):
// their count reaches the players with the next room_state.
TEST_F(RoomTest, SpectatorChurnSendsThePlayersNothing) {
    seat_both();
    a_->clear();
    b_->clear();
    for (int i = 0; i < 10; ++i) {
        auto s = std::make_shared<FakePeer>(100 + i, "Watcher");
        ASSERT_FALSE(room_.join(s, proto::Role::Spectator));
        EXPECT_EQ(s->all<proto::RoomState>().size(), 1U);
        EXPECT_EQ(s->all<proto::Snapshot>().size(), 1U);
        room_.leave(*s);
    }
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    EXPECT_TRUE(a_->received.empty());
    EXPECT_TRUE(b_->received.empty());
    EXPECT_EQ(watcher_->last_room_state().spectators, 1);
    room_.shoot(*a_, break_shot(0));
    play_out();
    EXPECT_EQ(a_->last_room_state().spectators, 1);
    EXPECT_EQ(b_->last_room_state().spectators, 1);
}

} // namespace
} // namespace carrom::room
