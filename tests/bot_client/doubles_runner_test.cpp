// The runner and MatchView in a doubles room (four seats in room_state): the rules' state has
// four seats on four sides, a side seat shoots from its own baseline, results count by team.
#include "carrom/bots/bot_runner.hpp"
#include "carrom/bots/match_view.hpp"
#include "carrom/bots/random_strategy.hpp"
#include "carrom/bots/shot_geometry.hpp"
#include "carrom/rules/match.hpp"
#include "fake_connection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace carrom::bots {
namespace {

using namespace std::chrono_literals;

rules::MatchState doubles_match() {
    rules::RulesConfig config;
    config.seat_count = 4;
    return rules::new_match(rules::RuleSet::Icf, config, PhysicsConfig{});
}

// A doubles room_state as the server sends it: four seats (bottom, right, top, left), seats 0
// and 2 playing white (seat 0 broke), one score and due entry per seat (its team's value).
proto::RoomState doubles_room(const rules::MatchState& match, int you) {
    proto::RoomState room;
    room.code = "ABCDEF";
    room.you = you;
    room.rule_set = proto::RuleSet::Icf;
    room.seats.resize(4);
    for (int s = 0; s < 4; ++s) {
        auto& seat = room.seats[static_cast<std::size_t>(s)];
        seat.occupied = true;
        seat.connected = true;
        seat.colour = s % 2 == 0 ? proto::Colour::White : proto::Colour::Black;
    }
    room.scores = {4, 7, 4, 7};
    room.dues = {1, 0, 1, 0};
    room.turn = match.turn_number;
    room.to_play = match.turn_seat;
    room.phase = proto::Phase::Aiming;
    for (const Body& body : match.bodies) {
        room.bodies.push_back(proto::to_board_body(body));
    }
    return room;
}

TEST(DoublesMatchView, FourSeatsOnFourSidesWithTeamScores) {
    rules::MatchState match = doubles_match();
    match.turn_seat = 2;
    const rules::MatchState state = match_state_from(doubles_room(match, 2));
    EXPECT_EQ(state.config.seat_count, 4);
    ASSERT_EQ(state.seats.size(), 4u);
    const rules::Side sides[] = {rules::Side::Bottom, rules::Side::Right, rules::Side::Top,
                                 rules::Side::Left};
    for (std::size_t s = 0; s < 4; ++s) {
        EXPECT_EQ(state.seats[s].side, sides[s]);
        EXPECT_EQ(state.seats[s].team, static_cast<int>(s % 2));
    }
    EXPECT_EQ(state.scores, (std::vector<int>{4, 7}));    // per team
    EXPECT_EQ(state.dues_owed, (std::vector<int>{1, 0})); // per team
    EXPECT_EQ(state.turn_seat, 2);
    // A fresh board with seat 2 to play: seat 2 breaks it (its team plays white).
    EXPECT_FALSE(state.break_done);
    EXPECT_EQ(state.breaker, 2);
    EXPECT_EQ(rules::team_colour(state, 0), BodyKind::White);
    EXPECT_EQ(rules::team_colour(state, 1), BodyKind::Black);
    EXPECT_EQ(state.missed_turns.size(), 4u);
}

TEST(DoublesMatchView, AfterTheBreakTheBreakerIsTheFirstWhiteSeat) {
    rules::MatchState match = doubles_match();
    match.bodies[4].pos_px.x += 40.0; // the break moved a coin
    match.turn_seat = 3;
    const rules::MatchState state = match_state_from(doubles_room(match, 3));
    EXPECT_TRUE(state.break_done);
    EXPECT_EQ(state.breaker, 0);
    EXPECT_EQ(rules::team_colour(state, rules::team_of(state, 3)), BodyKind::Black);
}

class DoublesRunnerTest : public ::testing::Test {
protected:
    void start(RandomStrategy& strategy) {
        runner_ = std::make_unique<BotRunner>(BotConfig{}, strategy);
        runner_->connect = [this](const BotConfig&) {
            return std::make_unique<fake::FakeConnection>(wire_);
        };
        runner_->start();
        deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    }
    void deliver(proto::ServerMessage message) {
        wire_.inbox.push_back(std::move(message));
        runner_->step(0ms);
    }
    std::vector<proto::Shoot> shots() const {
        std::vector<proto::Shoot> out;
        for (const auto& m : wire_.sent) {
            if (const auto* s = std::get_if<proto::Shoot>(&m)) {
                out.push_back(*s);
            }
        }
        return out;
    }

    fake::FakeWire wire_;
    std::unique_ptr<BotRunner> runner_;
};

TEST_F(DoublesRunnerTest, ASideSeatShootsFromItsOwnBaselineIntoTheBoard) {
    for (const int seat : {1, 3}) {
        wire_ = {};
        RandomStrategy strategy(static_cast<std::uint64_t>(seat));
        start(strategy);
        rules::MatchState match = doubles_match();
        match.bodies[4].pos_px.x += 40.0;
        match.turn_seat = seat;
        match.turn_number = 5;
        deliver(doubles_room(match, seat));
        ASSERT_EQ(shots().size(), 1u) << "seat " << seat;
        const proto::Shoot shoot = shots()[0];
        EXPECT_EQ(shoot.turn, 5);
        const Shot shot{shoot.x_px, shoot.angle_rad, shoot.power};
        EXPECT_TRUE(shot_is_legal(match, seat, shot)) << "seat " << seat;
        const double ahead = seat == 1 ? std::numbers::pi : 0.0; // right: -x; left: +x
        EXPECT_LE(std::abs(std::remainder(shoot.angle_rad - ahead, 2.0 * std::numbers::pi)),
                  75.0 * std::numbers::pi / 180.0 + 1e-9)
            << "seat " << seat << " angle " << shoot.angle_rad;
        EXPECT_EQ(runner_->summary().seat, seat);
        EXPECT_EQ(runner_->summary().team, seat % 2);
    }
}

TEST(DoublesRunner, AsksForADoublesRoomOrQuickMatch) {
    fake::FakeWire wire;
    RandomStrategy strategy(1);
    for (const JoinMode mode : {JoinMode::Create, JoinMode::Quick}) {
        wire = {};
        BotConfig config;
        config.mode = mode;
        config.create.seats = 4;
        config.quick_rule_set = proto::RuleSet::Seed;
        config.quick_seats = 4;
        BotRunner runner(config, strategy);
        runner.connect = [&](const BotConfig&) {
            return std::make_unique<fake::FakeConnection>(wire);
        };
        runner.start();
        wire.inbox.push_back(proto::Welcome{1, 7, std::string(32, 'a'), 0});
        runner.step(0ms);
        ASSERT_EQ(wire.sent.size(), 2u);
        if (mode == JoinMode::Create) {
            EXPECT_EQ(std::get<proto::CreateRoom>(wire.sent[1]).seats, 4);
        } else {
            EXPECT_EQ(std::get<proto::QuickMatch>(wire.sent[1]),
                      (proto::QuickMatch{proto::RuleSet::Seed, 4}));
        }
    }
}

TEST_F(DoublesRunnerTest, TheWinnerIsATeamAndPartnersBothWin) {
    for (const int seat : {0, 1, 2, 3}) {
        wire_ = {};
        RandomStrategy strategy(1);
        start(strategy);
        rules::MatchState match = doubles_match();
        match.turn_seat = (seat + 1) % 4; // someone else's turn: nothing to play
        deliver(doubles_room(match, seat));
        // Team 0 (seats 0 and 2) won: game_end's winner is the team's number.
        deliver(proto::Event{proto::GameEndEvent{0, "score", {25, 3, 25, 3}}});
        EXPECT_EQ(runner_->summary().games, 1);
        EXPECT_EQ(runner_->summary().wins, seat % 2 == 0 ? 1 : 0) << "seat " << seat;
        EXPECT_EQ(runner_->summary().losses, seat % 2 == 1 ? 1 : 0) << "seat " << seat;
        EXPECT_EQ(runner_->summary().scores, (std::vector<int>{25, 3, 25, 3}));
    }
}

} // namespace
} // namespace carrom::bots
