// The room's logic without sockets: seats, the match driver, streaming, clocks and grace.
#include "carrom/room/room.hpp"

#include "room/fake_peer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

namespace carrom::room {
namespace {

using testing::FakePeer;

constexpr double kUp = -std::numbers::pi / 2.0;

class RoomTest : public ::testing::Test {
protected:
    RoomTest() : room_("ABCDEF", config(), clock_, counters_) {}

    static RoomConfig config() {
        RoomConfig c;
        c.rule_set = proto::RuleSet::Icf;
        c.rules.shot_clock_s = 0.0;
        c.snapshot_hz = 60.0;
        c.grace_s = 60.0;
        return c;
    }

    void seat_both() {
        ASSERT_FALSE(room_.join(a_, proto::Role::Player));
        ASSERT_FALSE(room_.join(b_, proto::Role::Player));
    }

    // Advances the manual clock in snapshot steps until the shot has finished.
    int play_out() {
        int ticks = 0;
        while (room_.phase() == proto::Phase::Moving && ticks < 100000) {
            const auto wake = room_.next_wake_ms();
            EXPECT_TRUE(wake.has_value());
            clock_.set_ms(std::max(clock_.now_ms(), *wake));
            room_.tick();
            ++ticks;
        }
        return ticks;
    }

    proto::Shoot break_shot(int turn) const { return {turn, 300.0, kUp, 25.0}; }

    ManualClock clock_;
    RoomCounters counters_;
    Room room_;
    std::shared_ptr<FakePeer> a_ = std::make_shared<FakePeer>(1, "Asha");
    std::shared_ptr<FakePeer> b_ = std::make_shared<FakePeer>(2, "Bo");
    std::shared_ptr<FakePeer> watcher_ = std::make_shared<FakePeer>(3, "Cy");
};

TEST_F(RoomTest, FirstPlayerWaits) {
    ASSERT_FALSE(room_.join(a_, proto::Role::Player));
    const auto state = a_->last_room_state();
    EXPECT_EQ(state.code, "ABCDEF");
    EXPECT_EQ(state.you, 0);
    EXPECT_EQ(state.phase, proto::Phase::Waiting);
    EXPECT_TRUE(state.seats[0].occupied);
    EXPECT_FALSE(state.seats[1].occupied);
    EXPECT_EQ(state.bodies.size(), 20U); // 19 pieces and the striker
    ASSERT_EQ(a_->all<proto::Snapshot>().size(), 1U);
    EXPECT_TRUE(a_->all<proto::Snapshot>()[0].keyframe);
    EXPECT_FALSE(room_.next_wake_ms().has_value()); // nothing to do at rest
}

TEST_F(RoomTest, SecondPlayerStartsTheGame) {
    seat_both();
    const auto state = b_->last_room_state();
    EXPECT_EQ(state.you, 1);
    EXPECT_EQ(state.phase, proto::Phase::Aiming);
    EXPECT_EQ(state.seats[0].baseline, Baseline::Bottom);
    EXPECT_EQ(state.seats[1].baseline, Baseline::Top);
    EXPECT_EQ(state.seats[0].colour, proto::Colour::White); // icf: the breaker plays white
    EXPECT_EQ(state.seats[1].name, "Bo");
    ASSERT_EQ(a_->events<proto::TurnEvent>().size(), 1U);
    EXPECT_EQ(a_->events<proto::TurnEvent>()[0].seat, 0);
    EXPECT_EQ(counters_.matches.load(), 1);
}

TEST_F(RoomTest, ThirdPlayerFindsTheRoomFull) {
    seat_both();
    auto c = std::make_shared<FakePeer>(9, "Dee");
    const auto error = room_.join(c, proto::Role::Player);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "room_full");
    EXPECT_FALSE(room_.join(c, proto::Role::Spectator));
    EXPECT_EQ(c->last_room_state().you, -1);
    EXPECT_EQ(c->last_room_state().spectators, 1);
}

// A member's first room state is never superseded in its queue (it must arrive before the
// join keyframe); later broadcasts may be.
TEST_F(RoomTest, AJoinersFirstRoomStateIsNeverSuperseded) {
    seat_both();
    ASSERT_FALSE(a_->kinds.empty());
    EXPECT_TRUE(std::holds_alternative<proto::RoomState>(a_->received[0]));
    EXPECT_EQ(a_->kinds[0], MessageKind::Normal);
    ASSERT_FALSE(b_->kinds.empty());
    EXPECT_TRUE(std::holds_alternative<proto::RoomState>(b_->received[0]));
    EXPECT_EQ(b_->kinds[0], MessageKind::Normal);
    // a's copy of the state b's arrival broadcast is an ordinary, replaceable one.
    ASSERT_GE(a_->kinds.size(), 3U); // room state, join keyframe, then b's arrival
    EXPECT_TRUE(std::holds_alternative<proto::RoomState>(a_->received[2]));
    EXPECT_EQ(a_->kinds[2], MessageKind::State);
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

TEST_F(RoomTest, JoiningTwiceIsRefused) {
    ASSERT_FALSE(room_.join(a_, proto::Role::Player));
    const auto error = room_.join(a_, proto::Role::Spectator);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "already_in_room");
}

TEST_F(RoomTest, ShotBeforeTheOpponentArrivesIsWrongPhase) {
    ASSERT_FALSE(room_.join(a_, proto::Role::Player));
    room_.shoot(*a_, break_shot(0));
    EXPECT_EQ(a_->last_error(), "wrong_phase");
}

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
        EXPECT_EQ(board[b.id].pos_px, b.pos_px) << "body " << b.id;
        EXPECT_EQ(board[b.id].vel_px_s, (Vec2{0.0, 0.0})) << "body " << b.id;
    }
    for (int id : pocketed) {
        if (id != kStrikerId && returned.count(id) == 0) {
            EXPECT_NE(std::find(final_frame.pocketed.begin(), final_frame.pocketed.end(), id),
                      final_frame.pocketed.end());
        }
    }
}

TEST_F(RoomTest, InputDuringMotionIsRefused) {
    seat_both();
    room_.shoot(*a_, break_shot(0));
    room_.shoot(*a_, break_shot(0)); // a double click
    EXPECT_EQ(a_->last_error(), "in_motion");
    room_.aim(*b_, {1, 200.0});
    EXPECT_EQ(b_->last_error(), "in_motion");
    play_out();
    EXPECT_EQ(counters_.shots_total.load(), 1);
}

TEST_F(RoomTest, StaleAndOutOfTurnInputChangesNothing) {
    seat_both();
    room_.shoot(*b_, break_shot(0));
    EXPECT_EQ(b_->last_error(), "not_your_turn");
    room_.shoot(*a_, break_shot(5));
    EXPECT_EQ(a_->last_error(), "stale_turn");
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    room_.shoot(*a_, break_shot(0));
    play_out();
    const int turn = room_.match().turn_number;
    const int seat = room_.match().turn_seat;
    auto& shooter = seat == 0 ? *a_ : *b_;
    room_.shoot(shooter, break_shot(0)); // the old turn number, replayed
    EXPECT_EQ(shooter.last_error(), "stale_turn");
    EXPECT_EQ(room_.match().turn_number, turn);
    EXPECT_EQ(counters_.shots_total.load(), 1);
}

TEST_F(RoomTest, SpectatorsCannotPlay) {
    seat_both();
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    room_.shoot(*watcher_, break_shot(0));
    EXPECT_EQ(watcher_->last_error(), "spectator");
    room_.aim(*watcher_, {0, 300.0});
    EXPECT_EQ(watcher_->last_error(), "spectator");
    room_.rematch(*watcher_);
    EXPECT_EQ(watcher_->last_error(), "spectator");
    auto stranger = std::make_shared<FakePeer>(8, "X");
    room_.shoot(*stranger, break_shot(0));
    EXPECT_EQ(stranger->last_error(), "not_in_room");
}

TEST_F(RoomTest, IllegalPlacementAndPower) {
    seat_both();
    room_.shoot(*a_, {0, 50.0, kUp, 10.0}); // off the baseline range
    EXPECT_EQ(a_->last_error(), "illegal_placement");
    room_.shoot(*a_, {0, 300.0, kUp, 26.0}); // over max power
    EXPECT_EQ(a_->last_error(), "illegal_shot");
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    room_.shoot(*a_, break_shot(0));
    EXPECT_EQ(room_.phase(), proto::Phase::Moving);
}

TEST_F(RoomTest, AimIsRelayedToOthersOnly) {
    seat_both();
    a_->clear();
    b_->clear();
    room_.aim(*a_, {0, 250.5});
    EXPECT_TRUE(a_->events<proto::AimEvent>().empty());
    ASSERT_EQ(b_->events<proto::AimEvent>().size(), 1U);
    EXPECT_EQ(b_->events<proto::AimEvent>()[0], (proto::AimEvent{0, 0, 250.5}));
    EXPECT_EQ(b_->kinds.back(), MessageKind::Cue); // droppable, and asks for no keyframe
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

TEST_F(RoomTest, DropThenResumeMidShot) {
    seat_both();
    room_.shoot(*a_, break_shot(0));
    clock_.advance_ms(100);
    room_.tick();
    room_.disconnected(*b_);
    const auto dropped = a_->events<proto::PlayerDroppedEvent>();
    ASSERT_EQ(dropped.size(), 1U);
    EXPECT_EQ(dropped[0].seat, 1);
    EXPECT_EQ(dropped[0].grace_deadline_ms - dropped[0].server_time_ms, 60000);
    EXPECT_FALSE(a_->last_room_state().seats[1].connected);
    auto b2 = std::make_shared<FakePeer>(2, "Bo");
    ASSERT_FALSE(room_.resume(b2));
    ASSERT_EQ(a_->events<proto::PlayerReturnedEvent>().size(), 1U);
    EXPECT_EQ(b2->last_room_state().you, 1);
    EXPECT_EQ(b2->last_room_state().phase, proto::Phase::Moving);
    const auto snaps = b2->all<proto::Snapshot>();
    ASSERT_EQ(snaps.size(), 1U);
    EXPECT_TRUE(snaps[0].keyframe);
    EXPECT_EQ(snaps[0].seq, room_.seq());
    EXPECT_GT(snaps[0].t_s, 0.0);
    play_out();
    EXPECT_EQ(b2->all<proto::ShotResult>().size(), 1U);
    EXPECT_TRUE(b_->all<proto::ShotResult>().empty()); // the old connection hears nothing
}

TEST_F(RoomTest, ResumeReplacesAConnectedSession) {
    seat_both();
    auto b2 = std::make_shared<FakePeer>(2, "Bo");
    ASSERT_FALSE(room_.resume(b2));
    EXPECT_EQ(b_->last_error(), "replaced");
    EXPECT_EQ(b_->closed_with, proto::kCloseReplaced);
    room_.disconnected(*b_); // the old connection's close arrives later: ignored
    EXPECT_TRUE(a_->events<proto::PlayerDroppedEvent>().empty());
    EXPECT_TRUE(a_->last_room_state().seats[1].connected);
}

TEST_F(RoomTest, ResumeWithoutASeatIsABadToken) {
    seat_both();
    auto stranger = std::make_shared<FakePeer>(77, "X");
    const auto error = room_.resume(stranger);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "bad_token");
}

TEST_F(RoomTest, GraceExpiryForfeits) {
    seat_both();
    room_.disconnected(*b_);
    ASSERT_EQ(room_.next_wake_ms(), clock_.now_ms() + 60000);
    clock_.advance_ms(59999);
    room_.tick();
    EXPECT_TRUE(a_->events<proto::GameEndEvent>().empty());
    clock_.advance_ms(1);
    room_.tick();
    const auto ends = a_->events<proto::GameEndEvent>();
    ASSERT_EQ(ends.size(), 1U);
    EXPECT_EQ(ends[0].winner, 0);
    EXPECT_EQ(ends[0].reason, "forfeit");
    EXPECT_EQ(room_.phase(), proto::Phase::GameOver);
    EXPECT_FALSE(a_->last_room_state().seats[1].occupied);
    EXPECT_EQ(counters_.matches_finished_total.load(), 1);
}

TEST_F(RoomTest, LeavingForfeitsAndAbandonsTheRoomWhenEmpty) {
    seat_both();
    room_.leave(*a_);
    const auto ends = b_->events<proto::GameEndEvent>();
    ASSERT_EQ(ends.size(), 1U);
    EXPECT_EQ(ends[0].winner, 1);
    EXPECT_EQ(ends[0].reason, "left");
    EXPECT_FALSE(room_.abandoned());
    room_.leave(*b_);
    EXPECT_TRUE(room_.abandoned());
}

TEST_F(RoomTest, ShotClockPassesTheTurn) {
    RoomConfig c = config();
    c.rules.shot_clock_s = 10.0;
    Room room("ABCDEF", c, clock_, counters_);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.join(b_, proto::Role::Player));
    const auto turn = a_->events<proto::TurnEvent>().back();
    ASSERT_TRUE(turn.deadline_ms);
    EXPECT_EQ(*turn.deadline_ms - turn.server_time_ms, 10000);
    EXPECT_EQ(a_->last_room_state().shot_clock_deadline_ms, turn.deadline_ms);
    // The rules allow 0.5 s of latency grace past the advertised deadline.
    ASSERT_EQ(room.next_wake_ms(), clock_.now_ms() + 10501);
    clock_.advance_ms(10500);
    room.tick();
    EXPECT_EQ(room.match().turn_seat, 0);
    clock_.advance_ms(1);
    room.tick();
    EXPECT_EQ(room.match().turn_seat, 1);
    EXPECT_EQ(room.match().turn_number, 1);
    const auto fouls = b_->events<proto::FoulEvent>();
    ASSERT_EQ(fouls.size(), 1U);
    EXPECT_EQ(fouls[0].rule, "shot_clock_expired");
    EXPECT_EQ(b_->events<proto::TurnEvent>().back().seat, 1);
}

TEST_F(RoomTest, RematchAfterGameOver) {
    seat_both();
    room_.rematch(*a_);
    EXPECT_EQ(a_->last_error(), "wrong_phase");
    room_.disconnected(*b_);
    clock_.advance_ms(60000);
    room_.tick(); // b forfeits, seat freed
    auto c = std::make_shared<FakePeer>(5, "Cal");
    ASSERT_FALSE(room_.join(c, proto::Role::Player));
    const int old_turn = room_.match().turn_number;
    room_.rematch(*a_);
    EXPECT_EQ(room_.phase(), proto::Phase::GameOver);
    room_.rematch(*c);
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    EXPECT_GT(room_.match().turn_number, old_turn); // old inputs stay stale
    EXPECT_EQ(room_.match().turn_seat, 1);          // the break alternates
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

class ScriptedBrain final : public BotBrain {
public:
    Shot choose_shot(const rules::MatchState&, int, std::chrono::milliseconds) override {
        return {300.0, 1.2, 5.0};
    }
};

TEST_F(RoomTest, BotSeatTakesItsTurnThroughTheSeam) {
    RoomConfig c = config();
    c.rule_set = proto::RuleSet::Freestyle; // no break rule: a quiet shot passes the turn
    Room room("ABCDEF", c, clock_, counters_);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<ScriptedBrain>()));
    EXPECT_TRUE(a_->last_room_state().seats[1].bot);
    EXPECT_FALSE(room.take_bot_turn()); // seat 0 breaks
    auto early = room.bot_shoot(1, 0, {300.0, kUp, 10.0});
    ASSERT_TRUE(early);
    EXPECT_EQ(early->code, "not_your_turn");
    room.shoot(*a_, {0, 300.0, 0.0, 2.0}); // a soft shot along the baseline: nothing pocketed
    while (room.phase() == proto::Phase::Moving) {
        clock_.set_ms(*room.next_wake_ms());
        room.tick();
    }
    ASSERT_EQ(room.match().turn_seat, 1);
    auto turn = room.take_bot_turn();
    ASSERT_TRUE(turn);
    EXPECT_EQ(turn->seat, 1);
    EXPECT_EQ(turn->turn, room.match().turn_number);
    EXPECT_FALSE(room.take_bot_turn()); // handed out once per turn
    const Shot shot = turn->brain->choose_shot(turn->state, turn->seat, {});
    EXPECT_FALSE(room.bot_shoot(turn->seat, turn->turn, {shot.x_px, -kUp, 10.0}));
    EXPECT_EQ(room.phase(), proto::Phase::Moving);
    EXPECT_FALSE(room.abandoned());
    room.leave(*a_);
    EXPECT_TRUE(room.abandoned()); // bots alone do not keep a room open
}

TEST_F(RoomTest, BotsAndPlayersTakeSeatsTheSameWay) {
    ASSERT_FALSE(room_.seat_bot("Bot", std::make_shared<ScriptedBrain>())); // seat 0
    EXPECT_EQ(room_.phase(), proto::Phase::Waiting);
    ASSERT_FALSE(room_.join(a_, proto::Role::Player)); // seat 1: the game starts
    EXPECT_EQ(room_.seat_of(*a_), 1);
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    EXPECT_EQ(a_->last_room_state().you, 1);
    ASSERT_EQ(a_->all<proto::Snapshot>().size(), 1U);
    EXPECT_TRUE(a_->all<proto::Snapshot>()[0].keyframe);
    ASSERT_EQ(a_->events<proto::TurnEvent>().size(), 1U);
    EXPECT_EQ(a_->events<proto::TurnEvent>()[0].seat, 0);
    EXPECT_EQ(counters_.matches_started_total.load(), 1);
    const auto bot_error = room_.seat_bot("Another bot", std::make_shared<ScriptedBrain>());
    const auto player_error = room_.join(b_, proto::Role::Player);
    ASSERT_TRUE(bot_error && player_error);
    EXPECT_EQ(*bot_error, *player_error);
    EXPECT_EQ(bot_error->code, "room_full");
    EXPECT_EQ(a_->events<proto::TurnEvent>().size(), 1U);
}

// Records what the room tells its observer, one line per notice.
class RecordingObserver final : public RoomObserver {
public:
    void member(const MemberNotice& n) override {
        static constexpr const char* kChange[] = {"joined", "dropped", "returned", "left"};
        lines.push_back(std::string(kChange[static_cast<int>(n.change)]) + " " + n.name + " " +
                        std::to_string(n.seat) + (n.bot ? " bot" : ""));
    }
    void game_over(const proto::GameEndEvent& end) override {
        std::string line = "game over " + std::to_string(end.winner) + " " + end.reason;
        for (const int score : end.scores) {
            line += " " + std::to_string(score);
        }
        lines.push_back(line);
    }
    std::vector<std::string> lines;
};

TEST_F(RoomTest, TheObserverHearsMembersAndGameEnds) {
    RecordingObserver observer;
    Room room("ABCDEF", config(), clock_, counters_, &observer);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<ScriptedBrain>()));
    ASSERT_FALSE(room.join(watcher_, proto::Role::Spectator));
    room.disconnected(*a_);
    ASSERT_FALSE(room.resume(a_));
    room.leave(*watcher_);
    room.leave(*a_); // forfeits the running game
    EXPECT_EQ(observer.lines,
              (std::vector<std::string>{"joined Asha 0", "joined Bot 1 bot", "joined Cy -1",
                                        "dropped Asha 0", "returned Asha 0", "left Cy -1",
                                        "left Asha 0", "game over 1 left 0 0"}));
}

TEST_F(RoomTest, TheObserverHearsWhenTheGracePeriodEnds) {
    RecordingObserver observer;
    Room room("ABCDEF", config(), clock_, counters_, &observer);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.join(b_, proto::Role::Player));
    room.disconnected(*b_);
    clock_.advance_ms(60000);
    room.tick();
    EXPECT_EQ(observer.lines,
              (std::vector<std::string>{"joined Asha 0", "joined Bo 1", "dropped Bo 1", "left Bo 1",
                                        "game over 0 forfeit 0 0"}));
}

TEST(RoomOptions, MakeRulesConfig) {
    proto::RoomOptions options;
    options.target_points = 50;
    options.boards = 3;
    options.shot_clock_s = 12.0;
    const auto icf = make_rules_config(proto::RuleSet::Icf, options, 20.0);
    EXPECT_EQ(icf.target_points, 50);
    EXPECT_EQ(icf.max_boards, 3);
    EXPECT_EQ(icf.shot_clock_s, 12.0);
    const auto free = make_rules_config(proto::RuleSet::Freestyle, options, 20.0);
    EXPECT_EQ(free.freestyle.target, 50);
    const auto defaults = make_rules_config(proto::RuleSet::Icf, {}, 15.0);
    EXPECT_EQ(defaults.shot_clock_s, 15.0);
    EXPECT_EQ(defaults.target_points, 25);
}

} // namespace
} // namespace carrom::room
