// Bot seats: taken like a player's, and played through the seam the server drives (take_bot_turn,
// then bot_shoot).
#include "room/room_fixture.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace carrom::room {
namespace {

using testing::kUp;
using testing::RoomTest;
using testing::ScriptedBrain;

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

} // namespace
} // namespace carrom::room
