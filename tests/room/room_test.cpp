// The room's logic without sockets: seats, joins and leaves, the checks on players' input, the
// shot clock and the rematch.
#include "room/room_fixture.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <variant>

namespace carrom::room {
namespace {

using testing::FakePeer;
using testing::kUp;
using testing::RoomTest;

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
    EXPECT_EQ(state.seats[0].baseline, proto::Baseline::Bottom);
    EXPECT_EQ(state.seats[1].baseline, proto::Baseline::Top);
    EXPECT_EQ(state.seats[0].team, 0);
    EXPECT_EQ(state.seats[1].team, 1);
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

TEST_F(RoomTest, ARoomWaitsForPlayersWhileSomeoneIsInItAndNoGameHasBegun) {
    EXPECT_FALSE(room_.waiting_for_players()); // nobody in it
    auto watcher = std::make_shared<FakePeer>(9, "Dee");
    ASSERT_FALSE(room_.join(watcher, proto::Role::Spectator));
    EXPECT_TRUE(room_.waiting_for_players());
    ASSERT_FALSE(room_.join(a_, proto::Role::Player));
    EXPECT_TRUE(room_.waiting_for_players());
    ASSERT_FALSE(room_.join(b_, proto::Role::Player));
    EXPECT_FALSE(room_.waiting_for_players()); // the game began
    room_.leave(*b_);
    EXPECT_FALSE(room_.waiting_for_players()); // (and it stays begun)
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
