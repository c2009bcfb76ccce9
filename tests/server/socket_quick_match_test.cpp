// Quick match over real sockets: two waiting players are paired, and a lone waiter gets a server
// bot after the configured wait (never with a wait of zero, nor after leaving the queue).
#include "server/socket_fixture.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using testing::SocketTest;
using testing::test_settings;

// A server bot that always plays a soft shot along its baseline, and counts the brains made.
class SoftShotBrain final : public room::BotBrain {
public:
    Shot choose_shot(const rules::MatchState&, int, std::chrono::milliseconds) override {
        return {300.0, 0.0, 2.0};
    }
};

struct CountingBots {
    std::shared_ptr<std::atomic<int>> made = std::make_shared<std::atomic<int>>(0);
    std::shared_ptr<std::atomic<int>> last_level = std::make_shared<std::atomic<int>>(-1);
    BotFactory factory() const {
        return [count = made, level_seen = last_level](proto::BotLevel level) {
            ++*count;
            *level_seen = static_cast<int>(level);
            return std::make_shared<SoftShotBrain>();
        };
    }
};

ServerSettings quick_bot_settings(double wait_s) {
    ServerSettings s = test_settings();
    s.quick_match_bot_s = wait_s;
    s.time_scale = 10.0; // shots play fast
    return s;
}

TEST_F(SocketTest, QuickMatchPairsTwoWaitingPlayers) {
    start();
    auto a = connect("Asha");
    auto b = connect("Bo");
    a->send(proto::QuickMatch{proto::RuleSet::Seed});
    b->send(proto::QuickMatch{proto::RuleSet::Seed});
    ASSERT_TRUE(a->wait_for_event<proto::TurnEvent>());
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    const auto room_a = a->logged<proto::RoomState>().back();
    const auto room_b = b->logged<proto::RoomState>().back();
    EXPECT_EQ(room_a.rule_set, proto::RuleSet::Seed);
    EXPECT_EQ(room_a.code, room_b.code);
    EXPECT_NE(room_a.you, room_b.you);
}

TEST_F(SocketTest, QuickMatchSeatsABotAfterTheWaitAndTheBotPlays) {
    CountingBots bots;
    ServerSettings s = quick_bot_settings(0.2);
    s.quick_match_bot_level = proto::BotLevel::Hard;
    start(s, bots.factory());
    auto a = connect("Asha");
    const auto asked = std::chrono::steady_clock::now();
    a->send(proto::QuickMatch{proto::RuleSet::Freestyle});
    std::optional<proto::RoomState> state;
    for (int i = 0; i < 4 && !(state && state->seats[1].bot); ++i) {
        state = a->wait_for<proto::RoomState>(3000ms);
        ASSERT_TRUE(state);
    }
    ASSERT_TRUE(state && state->seats[1].bot);
    EXPECT_GE(std::chrono::steady_clock::now() - asked, 190ms); // not before the wait
    EXPECT_EQ(state->you, 0);
    EXPECT_EQ(state->rule_set, proto::RuleSet::Freestyle);
    EXPECT_EQ(state->seats[1].name, "Bot (hard)");
    EXPECT_EQ(*bots.made, 1);
    EXPECT_EQ(*bots.last_level, static_cast<int>(proto::BotLevel::Hard));
    const auto turn = a->wait_for_event<proto::TurnEvent>();
    ASSERT_TRUE(turn);
    ASSERT_EQ(turn->seat, 0);
    a->send(proto::Shoot{turn->turn, 300.0, 0.0, 2.0}); // soft, along the baseline: bot's turn
    const auto mine = a->wait_for<proto::ShotResult>(5000ms);
    ASSERT_TRUE(mine);
    EXPECT_EQ(mine->seat, 0);
    EXPECT_EQ(mine->next_seat, 1);
    const auto bots_shot = a->wait_for<proto::ShotResult>(5000ms); // the bot shoots by itself
    ASSERT_TRUE(bots_shot);
    EXPECT_EQ(bots_shot->seat, 1);
    EXPECT_EQ(bots_shot->turn, mine->next_turn);
}

TEST_F(SocketTest, QuickMatchPartnerBeforeTheWaitMeansNoBot) {
    CountingBots bots;
    start(quick_bot_settings(0.3), bots.factory());
    auto a = connect("Asha");
    auto b = connect("Bo");
    a->send(proto::QuickMatch{proto::RuleSet::Icf});
    b->send(proto::QuickMatch{proto::RuleSet::Icf});
    ASSERT_TRUE(a->wait_for_event<proto::TurnEvent>());
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    const auto room = a->logged<proto::RoomState>().back();
    EXPECT_FALSE(room.seats[0].bot);
    EXPECT_FALSE(room.seats[1].bot);
    EXPECT_EQ(room.code, b->logged<proto::RoomState>().back().code);
    // Past the wait: no bot room, nothing more for either player.
    EXPECT_FALSE(a->read(500ms));
    EXPECT_EQ(*bots.made, 0);
    EXPECT_EQ(server_->metrics().rooms.load(), 1);
}

TEST_F(SocketTest, QuickMatchWaitersWhoLeaveGetNoBot) {
    CountingBots bots;
    start(quick_bot_settings(0.2), bots.factory());
    auto leaver = connect("Lee");
    auto dropper = connect("Dee");
    auto creator = connect("Cy");
    leaver->send(proto::QuickMatch{proto::RuleSet::Icf});
    dropper->send(proto::QuickMatch{proto::RuleSet::Seed});
    creator->send(proto::QuickMatch{proto::RuleSet::DiscPool});
    leaver->send(proto::Leave{});
    dropper->drop();
    creator->send(proto::CreateRoom{});
    const auto own = creator->wait_for<proto::RoomState>();
    ASSERT_TRUE(own);
    EXPECT_FALSE(own->seats[1].occupied);
    EXPECT_FALSE(leaver->read(600ms)); // three waits have passed
    while (creator->read(50ms)) {      // its own room's keyframe; nobody joins it
    }
    for (const auto& state : creator->logged<proto::RoomState>()) {
        EXPECT_FALSE(state.seats[1].occupied);
    }
    EXPECT_EQ(*bots.made, 0);
    EXPECT_EQ(server_->metrics().rooms.load(), 1);
    // A waiter who left may queue again, and then does get its bot.
    auto again = connect("Al");
    again->send(proto::QuickMatch{proto::RuleSet::Icf});
    again->send(proto::Leave{});
    again->send(proto::QuickMatch{proto::RuleSet::Icf});
    std::optional<proto::RoomState> state;
    for (int i = 0; i < 4 && !(state && state->seats[1].bot); ++i) {
        state = again->wait_for<proto::RoomState>(3000ms);
        ASSERT_TRUE(state);
    }
    EXPECT_EQ(*bots.made, 1);
}

TEST_F(SocketTest, QuickMatchBotWaitZeroNeverSeatsABot) {
    CountingBots bots;
    start(quick_bot_settings(0.0), bots.factory());
    auto a = connect("Asha");
    a->send(proto::QuickMatch{proto::RuleSet::Icf});
    EXPECT_FALSE(a->read(400ms));
    EXPECT_EQ(*bots.made, 0);
    EXPECT_EQ(server_->metrics().rooms.load(), 0);
    auto b = connect("Bo"); // pairing still works
    b->send(proto::QuickMatch{proto::RuleSet::Icf});
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    const auto room = b->logged<proto::RoomState>().back();
    EXPECT_FALSE(room.seats[0].bot);
    EXPECT_FALSE(room.seats[1].bot);
}

} // namespace
} // namespace carrom::server
