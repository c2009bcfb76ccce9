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

// A draining server hands over only rooms it can make again from their config: none with a bot.
TEST_F(RoomTest, ARoomWithABotSeatIsNotOneThatWaitsForPlayers) {
    RoomConfig c = config();
    c.rules.seat_count = 4;
    Room room("ABCDEF", c, clock_, counters_);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    EXPECT_TRUE(room.waiting_for_players());
    ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<ScriptedBrain>()));
    EXPECT_EQ(room.phase(), proto::Phase::Waiting);
    EXPECT_FALSE(room.waiting_for_players());
}

TEST_F(RoomTest, BotSeatTakesItsTurnThroughTheSeam) {
    RoomConfig c = config();
    c.rule_set = proto::RuleSet::Freestyle; // no break rule: a quiet shot passes the turn
    Room room("ABCDEF", c, clock_, counters_);
    ASSERT_FALSE(room.join(a_, proto::Role::Player));
    ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<ScriptedBrain>()));
    EXPECT_TRUE(a_->last_room_state().seats[1].bot);
    EXPECT_FALSE(room.take_bot_turn()); // seat 0 breaks
    const BotShotOutcome early = room.bot_shoot(1, 0, {300.0, kUp, 10.0});
    ASSERT_TRUE(early.refused);
    EXPECT_EQ(early.refused->code, "not_your_turn");
    EXPECT_FALSE(early.replaced);
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
    const BotShotOutcome outcome = room.bot_shoot(turn->seat, turn->turn, {shot.x_px, -kUp, 10.0});
    EXPECT_FALSE(outcome.refused);
    EXPECT_FALSE(outcome.replaced);
    EXPECT_EQ(room.phase(), proto::Phase::Moving);
    EXPECT_FALSE(room.abandoned());
    room.leave(*a_);
    EXPECT_TRUE(room.abandoned()); // bots alone do not keep a room open
}

// A brain that places the striker off the board.
class OffTheBoardBrain final : public BotBrain {
public:
    Shot choose_shot(const rules::MatchState&, int, std::chrono::milliseconds) override {
        return {1e6, kUp, 10.0};
    }
};

TEST_F(RoomTest, BotShotTheRulesRefuseIsPlayedAsTheNearestLegalOne) {
    // No shot clock (the fixture's): a refused bot shot would leave the turn to nobody.
    ASSERT_FALSE(room_.seat_bot("Bot", std::make_shared<OffTheBoardBrain>())); // seat 0
    ASSERT_FALSE(room_.join(a_, proto::Role::Player));
    auto turn = room_.take_bot_turn();
    ASSERT_TRUE(turn);
    const Shot shot = turn->brain->choose_shot(turn->state, turn->seat, {});
    const BotShotOutcome outcome = room_.bot_shoot(turn->seat, turn->turn, shot);
    EXPECT_FALSE(outcome.refused);
    ASSERT_TRUE(outcome.replaced);
    EXPECT_EQ(outcome.replaced->code, "illegal_placement");
    EXPECT_EQ(room_.phase(), proto::Phase::Moving);
    while (room_.phase() == proto::Phase::Moving) {
        clock_.set_ms(*room_.next_wake_ms());
        room_.tick();
    }
    const auto results = a_->all<proto::ShotResult>();
    ASSERT_EQ(results.size(), 1U);
    EXPECT_EQ(results[0].seat, 0);
    EXPECT_EQ(results[0].x_px, 487.0); // the nearer end of the baseline
    EXPECT_EQ(results[0].angle_rad, kUp);
    EXPECT_EQ(results[0].power, 10.0);
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
