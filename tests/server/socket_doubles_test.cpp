// Doubles over real sockets: a four-seat room created and joined by four clients (turn order,
// seats, teams, a spectator), server bots at the seats asked, quick match for doubles with four
// players and with two players and bots after the wait, and bad seat fields refused.
#include "server/socket_fixture.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <numbers>
#include <optional>
#include <set>
#include <vector>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using testing::SocketTest;
using testing::test_settings;
using testing::WsTestClient;

// A soft shot along the seat's own baseline (x for bottom and top, y for right and left): it
// pockets nothing and passes the turn.
double along_baseline(rules::Side side) {
    return side == rules::Side::Bottom || side == rules::Side::Top ? 0.0 : std::numbers::pi / 2.0;
}

class BaselineShotBrain final : public room::BotBrain {
public:
    Shot choose_shot(const rules::MatchState& state, int seat, std::chrono::milliseconds) override {
        return {300.0, along_baseline(state.seats[static_cast<std::size_t>(seat)].side), 2.0};
    }
};

struct CountingDoublesBots {
    std::shared_ptr<std::atomic<int>> made = std::make_shared<std::atomic<int>>(0);
    BotFactory factory() const {
        return [count = made](proto::BotLevel) {
            ++*count;
            return std::make_shared<BaselineShotBrain>();
        };
    }
};

ServerSettings fast_settings(double quick_wait_s = 0.0) {
    ServerSettings s = test_settings();
    s.quick_match_bot_s = quick_wait_s;
    s.time_scale = 10.0; // shots play fast
    return s;
}

proto::CreateRoom doubles(std::optional<proto::BotSeat> bot = std::nullopt) {
    proto::CreateRoom create;
    create.rule_set = proto::RuleSet::Freestyle;
    create.seats = 4;
    create.bot = std::move(bot);
    return create;
}

// Reads room states until one shows every seat taken; returns it.
std::optional<proto::RoomState> wait_until_full(WsTestClient& client) {
    for (int i = 0; i < 10; ++i) {
        const auto state = client.wait_for<proto::RoomState>(3000ms);
        if (!state) {
            return std::nullopt;
        }
        bool full = true;
        for (const auto& seat : state->seats) {
            full = full && seat.occupied;
        }
        if (full) {
            return state;
        }
    }
    return std::nullopt;
}

// The seat to play shoots softly along its baseline; every client then sees its shot_result.
void soft_shot(WsTestClient& shooter, const proto::RoomState& state, int turn,
               std::vector<WsTestClient*> watchers, int expected_next) {
    const auto side = state.seats[static_cast<std::size_t>(state.you)].baseline;
    shooter.send(proto::Shoot{turn, 300.0, along_baseline(side), 2.0});
    for (WsTestClient* w : watchers) {
        const auto result = w->wait_for<proto::ShotResult>(5000ms);
        ASSERT_TRUE(result);
        EXPECT_EQ(result->seat, state.you);
        EXPECT_EQ(result->next_seat, expected_next);
        ASSERT_EQ(result->scores.size(), 4U);
    }
}

TEST_F(SocketTest, FourClientsCreateAndJoinADoublesRoomAndPlayInTurn) {
    start(fast_settings());
    std::vector<std::unique_ptr<WsTestClient>> c;
    for (const char* name : {"Asha", "Bo", "Cy", "Dee"}) {
        c.push_back(connect(name));
    }
    c[0]->send(doubles());
    const auto created = c[0]->wait_for<proto::RoomState>();
    ASSERT_TRUE(created);
    ASSERT_EQ(created->seats.size(), 4U);
    EXPECT_EQ(created->phase, proto::Phase::Waiting);
    std::vector<proto::RoomState> mine{*created};
    for (std::size_t i = 1; i < 4; ++i) {
        c[i]->send(proto::JoinRoom{created->code, proto::Role::Player});
        const auto joined = c[i]->wait_for<proto::RoomState>();
        ASSERT_TRUE(joined);
        EXPECT_EQ(joined->you, static_cast<int>(i));
        mine.push_back(*joined);
    }
    const proto::Baseline sides[] = {proto::Baseline::Bottom, proto::Baseline::Right,
                                     proto::Baseline::Top, proto::Baseline::Left};
    for (std::size_t i = 0; i < 4; ++i) {
        ASSERT_TRUE(c[i]->wait_for_event<proto::TurnEvent>());
        const auto state = c[i]->logged<proto::RoomState>().back();
        EXPECT_EQ(state.phase, proto::Phase::Aiming);
        EXPECT_EQ(state.seats[i].baseline, sides[i]);
        EXPECT_EQ(state.seats[i].team, static_cast<int>(i % 2));
        mine[i] = state;
    }
    auto fifth = connect("Eve");
    fifth->send(proto::JoinRoom{created->code, proto::Role::Player});
    EXPECT_EQ(fifth->wait_for_error(), "room_full");
    fifth->send(proto::JoinRoom{created->code, proto::Role::Spectator});
    const auto watching = fifth->wait_for<proto::RoomState>();
    ASSERT_TRUE(watching);
    EXPECT_EQ(watching->you, -1);
    EXPECT_EQ(watching->seats.size(), 4U);

    std::vector<WsTestClient*> everyone{c[0].get(), c[1].get(), c[2].get(), c[3].get(),
                                        fifth.get()};
    int turn = mine[0].turn;
    for (int seat : {0, 1, 2, 3}) {
        soft_shot(*c[static_cast<std::size_t>(seat)], mine[static_cast<std::size_t>(seat)], turn,
                  everyone, (seat + 1) % 4);
        ++turn;
    }
    for (auto& client : c) {
        EXPECT_TRUE(client->logged<proto::Error>().empty());
    }
}

TEST_F(SocketTest, ADoublesRoomWithABotPartnerWaitsForTwoOpponents) {
    CountingDoublesBots bots;
    start(fast_settings(), bots.factory());
    auto a = connect("Asha");
    a->send(doubles(proto::BotSeat{proto::BotLevel::Easy, {2}}));
    const auto first = a->wait_for<proto::RoomState>();
    ASSERT_TRUE(first);
    auto b = connect("Bo");
    auto d = connect("Dee");
    b->send(proto::JoinRoom{first->code, proto::Role::Player});
    d->send(proto::JoinRoom{first->code, proto::Role::Player});
    const auto full = wait_until_full(*a);
    ASSERT_TRUE(full);
    EXPECT_EQ(full->you, 0);
    EXPECT_FALSE(full->seats[1].bot);
    EXPECT_TRUE(full->seats[2].bot);
    EXPECT_EQ(full->seats[2].name, "Bot Kiran (easy)");
    EXPECT_FALSE(full->seats[3].bot);
    EXPECT_EQ(*bots.made, 1);
    ASSERT_TRUE(b->wait_for_event<proto::TurnEvent>());
    ASSERT_TRUE(d->wait_for_event<proto::TurnEvent>());
    std::set<int> yous{b->logged<proto::RoomState>().back().you,
                       d->logged<proto::RoomState>().back().you};
    EXPECT_EQ(yous, (std::set<int>{1, 3}));
}

TEST_F(SocketTest, ADoublesRoomWithThreeBotsStartsAtOnceAndTheBotsPlay) {
    CountingDoublesBots bots;
    start(fast_settings(), bots.factory());
    auto a = connect("Asha");
    a->send(doubles(proto::BotSeat{}));
    const auto full = wait_until_full(*a);
    ASSERT_TRUE(full);
    EXPECT_EQ(*bots.made, 3);
    EXPECT_TRUE(full->seats[1].bot && full->seats[2].bot && full->seats[3].bot);
    const auto turn = a->wait_for_event<proto::TurnEvent>();
    ASSERT_TRUE(turn);
    ASSERT_EQ(turn->seat, 0);
    a->send(proto::Shoot{turn->turn, 300.0, 0.0, 2.0});
    // The three bots play their turns by themselves, anticlockwise, back to seat 0.
    for (int seat : {0, 1, 2, 3}) {
        const auto result = a->wait_for<proto::ShotResult>(5000ms);
        ASSERT_TRUE(result);
        EXPECT_EQ(result->seat, seat);
        EXPECT_EQ(result->next_seat, (seat + 1) % 4);
    }
}

TEST_F(SocketTest, QuickMatchForDoublesGroupsFourPlayers) {
    CountingDoublesBots bots;
    start(fast_settings(5.0), bots.factory());
    std::vector<std::unique_ptr<WsTestClient>> c;
    for (const char* name : {"Asha", "Bo", "Cy", "Dee"}) {
        c.push_back(connect(name));
    }
    auto single = connect("Sol"); // a singles waiter of the same rule set is not grouped
    single->send(proto::QuickMatch{proto::RuleSet::Icf, 2});
    for (auto& client : c) {
        client->send(proto::QuickMatch{proto::RuleSet::Icf, 4});
    }
    std::set<int> yous;
    std::set<std::string> codes;
    for (auto& client : c) {
        ASSERT_TRUE(client->wait_for_event<proto::TurnEvent>());
        const auto state = client->logged<proto::RoomState>().back();
        ASSERT_EQ(state.seats.size(), 4U);
        for (const auto& seat : state.seats) {
            EXPECT_TRUE(seat.occupied);
            EXPECT_FALSE(seat.bot);
        }
        yous.insert(state.you);
        codes.insert(state.code);
    }
    EXPECT_EQ(yous, (std::set<int>{0, 1, 2, 3}));
    EXPECT_EQ(codes.size(), 1U);
    EXPECT_EQ(*bots.made, 0);
    EXPECT_FALSE(single->read(300ms)); // still waiting
}

TEST_F(SocketTest, QuickMatchForDoublesSeatsTwoWaitingPlayersWithBotsAfterTheWait) {
    CountingDoublesBots bots;
    start(fast_settings(0.3), bots.factory());
    auto a = connect("Asha");
    auto b = connect("Bo");
    const auto asked = std::chrono::steady_clock::now();
    a->send(proto::QuickMatch{proto::RuleSet::Freestyle, 4});
    b->send(proto::QuickMatch{proto::RuleSet::Freestyle, 4});
    const auto full_a = wait_until_full(*a);
    ASSERT_TRUE(full_a);
    EXPECT_GE(std::chrono::steady_clock::now() - asked, 290ms); // not before the wait
    const auto full_b = wait_until_full(*b);
    ASSERT_TRUE(full_b);
    EXPECT_EQ(full_a->code, full_b->code);
    EXPECT_EQ(std::set<int>({full_a->you, full_b->you}), (std::set<int>{0, 1}));
    EXPECT_FALSE(full_a->seats[0].bot);
    EXPECT_FALSE(full_a->seats[1].bot);
    EXPECT_TRUE(full_a->seats[2].bot);
    EXPECT_TRUE(full_a->seats[3].bot);
    EXPECT_EQ(*bots.made, 2);
    // Seat 0 and seat 1 are the humans: each plays its turn, the bots theirs.
    WsTestClient& seat0 = full_a->you == 0 ? *a : *b;
    WsTestClient& seat1 = full_a->you == 0 ? *b : *a;
    const auto turn = seat0.wait_for_event<proto::TurnEvent>();
    ASSERT_TRUE(turn);
    seat0.send(proto::Shoot{turn->turn, 300.0, 0.0, 2.0});
    const auto first = seat1.wait_for<proto::ShotResult>(5000ms);
    ASSERT_TRUE(first);
    EXPECT_EQ(first->next_seat, 1);
    seat1.send(proto::Shoot{first->next_turn, 300.0, std::numbers::pi / 2.0, 2.0});
    for (int seat : {0, 1, 2, 3}) {
        const auto result = seat0.wait_for<proto::ShotResult>(5000ms);
        ASSERT_TRUE(result);
        EXPECT_EQ(result->seat, seat);
    }
}

TEST_F(SocketTest, BadSeatFieldsAreRefusedWithBadField) {
    start(fast_settings());
    auto a = connect("Asha");
    a->send_text(R"({"type":"create_room","seats":3})");
    EXPECT_EQ(a->wait_for_error(), "bad_field");
    a->send_text(R"({"type":"create_room","seats":4,"bot":{"seats":[2,2]}})");
    EXPECT_EQ(a->wait_for_error(), "bad_field");
    a->send_text(R"({"type":"quick_match","seats":6})");
    EXPECT_EQ(a->wait_for_error(), "bad_field");
    EXPECT_EQ(server_->metrics().rooms.load(), 0);
}

} // namespace
} // namespace carrom::server
