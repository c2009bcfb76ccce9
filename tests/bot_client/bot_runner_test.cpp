// BotRunner's protocol logic against a fake connection: what it sends for each thing it hears.
#include "carrom/bots/bot_runner.hpp"
#include "carrom/bots/match_view.hpp"
#include "carrom/bots/scripted_strategy.hpp"
#include "carrom/rules/match.hpp"
#include "fake_connection.hpp"

#include <gtest/gtest.h>

namespace carrom::bots {
namespace {

using namespace std::chrono_literals;

using fake::FakeConnection;
using fake::FakeWire;

proto::RoomState room_for(const rules::MatchState& match, int you, proto::Phase phase) {
    proto::RoomState room;
    room.code = "ABCDEF";
    room.you = you;
    room.rule_set = proto::RuleSet::Icf;
    room.seats.resize(2);
    room.scores = {0, 0};
    room.dues = {0, 0};
    room.turn = match.turn_number;
    room.to_play = match.turn_seat;
    room.phase = phase;
    for (const Body& body : match.bodies) {
        room.bodies.push_back(proto::to_board_body(body));
    }
    return room;
}

class BotRunnerTest : public ::testing::Test {
protected:
    BotRunnerTest() : strategy_({{250.0, -1.4, 12.0}}) {}

    void start(BotConfig config) {
        runner_ = std::make_unique<BotRunner>(std::move(config), strategy_);
        runner_->connect = [this](const BotConfig&) {
            ++wire_.opened;
            wire_.status = wire_.refuse
                               ? net::ConnectionStatus{net::ConnectionState::Closed,
                                                       "Could not reach x:1: refused.", 0}
                               : net::ConnectionStatus{net::ConnectionState::Open, "fake", 0};
            return std::make_unique<FakeConnection>(wire_);
        };
        runner_->start();
    }
    void deliver(proto::ServerMessage message) {
        wire_.inbox.push_back(std::move(message));
        runner_->step(0ms);
    }
    template <class T> std::vector<T> sent() const {
        std::vector<T> out;
        for (const auto& m : wire_.sent) {
            if (const auto* t = std::get_if<T>(&m)) {
                out.push_back(*t);
            }
        }
        return out;
    }

    FakeWire wire_;
    ScriptedStrategy strategy_;
    std::unique_ptr<BotRunner> runner_;
    rules::MatchState match_ =
        rules::new_match(rules::RuleSet::Icf, rules::RulesConfig{}, PhysicsConfig{});
};

TEST_F(BotRunnerTest, HelloThenCreateRoomAfterWelcome) {
    BotConfig config;
    config.name = "Asha";
    config.mode = JoinMode::Create;
    config.create.rule_set = proto::RuleSet::Freestyle;
    start(config);
    ASSERT_EQ(wire_.sent.size(), 1u);
    EXPECT_EQ(std::get<proto::Hello>(wire_.sent[0]).name, "Asha");
    EXPECT_FALSE(std::get<proto::Hello>(wire_.sent[0]).resume_token);
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    ASSERT_EQ(sent<proto::CreateRoom>().size(), 1u);
    EXPECT_EQ(sent<proto::CreateRoom>()[0].rule_set, proto::RuleSet::Freestyle);
}

TEST_F(BotRunnerTest, JoinAndQuickAndSpectateAskForWhatTheySay) {
    BotConfig config;
    config.mode = JoinMode::Join;
    config.code = "K7M2QX";
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    EXPECT_EQ(sent<proto::JoinRoom>().at(0), (proto::JoinRoom{"K7M2QX", proto::Role::Player}));

    wire_ = {};
    config.mode = JoinMode::Spectate;
    start(config);
    deliver(proto::Welcome{1, 8, std::string(32, 'b'), 0});
    EXPECT_EQ(sent<proto::JoinRoom>().at(0), (proto::JoinRoom{"K7M2QX", proto::Role::Spectator}));

    wire_ = {};
    config.mode = JoinMode::Quick;
    config.quick_rule_set = proto::RuleSet::DiscPool;
    start(config);
    deliver(proto::Welcome{1, 9, std::string(32, 'c'), 0});
    EXPECT_EQ(sent<proto::QuickMatch>().at(0).rule_set, proto::RuleSet::DiscPool);
}

TEST_F(BotRunnerTest, ShootsOnceOnItsTurnWithTheTurnNumber) {
    start(BotConfig{});
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    match_.turn_number = 4;
    deliver(room_for(match_, 0, proto::Phase::Aiming));
    deliver(proto::Event{proto::TurnEvent{4, 0, std::nullopt, 0}}); // same turn: no second shot
    ASSERT_EQ(sent<proto::Shoot>().size(), 1u);
    EXPECT_EQ(sent<proto::Shoot>()[0], (proto::Shoot{4, 250.0, -1.4, 12.0}));
    ASSERT_EQ(sent<proto::Aim>().size(), 1u);
    EXPECT_EQ(sent<proto::Aim>()[0], (proto::Aim{4, 250.0}));
}

TEST_F(BotRunnerTest, WaitsOnTheOpponentsTurnAndPlaysOnTheTurnEvent) {
    start(BotConfig{});
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    match_.turn_seat = 1;
    deliver(room_for(match_, 0, proto::Phase::Aiming));
    EXPECT_TRUE(sent<proto::Shoot>().empty());
    deliver(proto::Event{proto::TurnEvent{1, 0, std::nullopt, 0}});
    ASSERT_EQ(sent<proto::Shoot>().size(), 1u);
    EXPECT_EQ(sent<proto::Shoot>()[0].turn, 1);
}

TEST_F(BotRunnerTest, SpectatorNeverShoots) {
    BotConfig config;
    config.mode = JoinMode::Spectate;
    config.code = "K7M2QX";
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    deliver(room_for(match_, -1, proto::Phase::Aiming));
    deliver(proto::Event{proto::TurnEvent{0, 0, std::nullopt, 0}});
    EXPECT_TRUE(sent<proto::Shoot>().empty());
}

TEST_F(BotRunnerTest, IllegalPlacementMakesItChooseAgain) {
    start(BotConfig{});
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    deliver(room_for(match_, 0, proto::Phase::Aiming));
    deliver(proto::Error{"illegal_placement", "The striker overlaps a coin."});
    ASSERT_EQ(sent<proto::Shoot>().size(), 2u);
    EXPECT_DOUBLE_EQ(sent<proto::Shoot>()[1].x_px, 253.0);
    EXPECT_EQ(runner_->summary().errors.at("illegal_placement"), 1);
    EXPECT_FALSE(runner_->done());
}

TEST_F(BotRunnerTest, GivesUpAfterTooManyRefusals) {
    BotConfig config;
    config.max_refusals = 3;
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    deliver(room_for(match_, 0, proto::Phase::Aiming));
    for (int i = 0; i < 4; ++i) {
        deliver(proto::Error{"illegal_shot", "No."});
    }
    EXPECT_TRUE(runner_->done());
    EXPECT_EQ(runner_->summary().failure, "Too many refused shots in a row; the last: No.");
}

TEST_F(BotRunnerTest, RematchUntilItsGamesArePlayedThenLeave) {
    BotConfig config;
    config.games = 2;
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    deliver(room_for(match_, 1, proto::Phase::Aiming));
    deliver(proto::Event{proto::GameEndEvent{1, "score", {3, 25}}});
    EXPECT_EQ(sent<proto::Rematch>().size(), 1u);
    EXPECT_FALSE(runner_->done());
    deliver(proto::Event{proto::GameEndEvent{0, "score", {25, 0}}});
    EXPECT_EQ(sent<proto::Leave>().size(), 1u);
    EXPECT_TRUE(runner_->done());
    const auto& summary = runner_->summary();
    EXPECT_TRUE(summary.finished);
    EXPECT_EQ(summary.games, 2);
    EXPECT_EQ(summary.wins, 1);
    EXPECT_EQ(summary.losses, 1);
    EXPECT_EQ(summary.scores, (std::vector<int>{25, 0}));
    EXPECT_EQ(summary.seat, 1);
    EXPECT_EQ(summary.room_code, "ABCDEF");
}

TEST_F(BotRunnerTest, FatalErrorStopsWithTheServersWords) {
    BotConfig config;
    config.mode = JoinMode::Join;
    config.code = "K7M2QX";
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'a'), 0});
    deliver(proto::Error{"room_not_found", "No room has the code K7M2QX."});
    EXPECT_TRUE(runner_->done());
    EXPECT_EQ(runner_->summary().failure,
              "The server said room_not_found: No room has the code K7M2QX.");
}

TEST_F(BotRunnerTest, ClosedConnectionIsAFailureUnlessDroppedOnPurpose) {
    start(BotConfig{});
    wire_.status = {net::ConnectionState::Closed, "Could not reach x:1: connection refused."};
    runner_->step(0ms);
    EXPECT_EQ(runner_->summary().failure, "Could not reach x:1: connection refused.");
}

// The I/O thread queues a message before it marks the link closed; a redirect and its close
// 4005 that land between a poll and the status are still a redirect, not a lost link.
TEST_F(BotRunnerTest, ARedirectAndItsCloseLandingJustAfterAPollAreFollowed) {
    BotConfig config;
    config.url = "ws://127.0.0.1:9/";
    config.mode = JoinMode::Join;
    config.code = "ABCDEF";
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'f'), 0});
    ASSERT_EQ(sent<proto::JoinRoom>().size(), 1U);
    wire_.after_poll = [this] {
        wire_.inbox.push_back(
            proto::Redirect{"ws://127.0.0.1:9/i/carrom-2/", "room", "ABCDEF", proto::Role::Player});
        wire_.status = {net::ConnectionState::Closed, "The server closed the connection.",
                        proto::kCloseRedirected};
    };
    runner_->step(0ms);
    EXPECT_FALSE(runner_->done()) << runner_->summary().failure;
    runner_->step(0ms);
    EXPECT_FALSE(runner_->done()) << runner_->summary().failure;
    EXPECT_EQ(runner_->summary().redirects, 1);
    EXPECT_EQ(wire_.opened, 2);
    deliver(proto::Welcome{2, 7, std::string(32, 'e'), 0});
    EXPECT_EQ(sent<proto::JoinRoom>().size(), 2U);
    EXPECT_EQ(sent<proto::JoinRoom>().back().code, "ABCDEF");
}

TEST_F(BotRunnerTest, ResumeSendsTheTokenAndKeepsTheSeat) {
    start(BotConfig{});
    const std::string token(32, 'f');
    deliver(proto::Welcome{1, 7, token, 0});
    deliver(room_for(match_, 0, proto::Phase::Moving));
    runner_->drop();
    runner_->step(0ms);
    EXPECT_FALSE(runner_->done());
    runner_->resume();
    EXPECT_EQ(wire_.opened, 2);
    EXPECT_EQ(std::get<proto::Hello>(wire_.sent.back()).resume_token, token);
    const auto requests = sent<proto::QuickMatch>().size();
    deliver(proto::Welcome{1, 7, token, 0});
    EXPECT_EQ(sent<proto::QuickMatch>().size(), requests); // no new room request
    EXPECT_EQ(runner_->summary().resumes, 0);              // not before the room is back
    deliver(room_for(match_, 0, proto::Phase::Moving));
    EXPECT_EQ(runner_->summary().resumes, 1);
    EXPECT_FALSE(runner_->done());
}

// Steps until `done` or 2 s pass.
template <class F> bool step_until(BotRunner& runner, F done) {
    const auto deadline = std::chrono::steady_clock::now() + 2s;
    while (!done() && std::chrono::steady_clock::now() < deadline) {
        runner.step(1ms);
    }
    return done();
}

TEST_F(BotRunnerTest, LostConnectionInARoomResumesByItselfAndPlaysTheDueShotAgain) {
    BotConfig config;
    config.reconnect = {0.002, 0.008, 5.0};
    start(config);
    std::vector<std::string> notices;
    runner_->on_notice = [&](const std::string& text) { notices.push_back(text); };
    const std::string token(32, 'f');
    deliver(proto::Welcome{1, 7, token, 0});
    deliver(room_for(match_, 0, proto::Phase::Aiming));
    ASSERT_EQ(sent<proto::Shoot>().size(), 1u); // into a connection that is about to break
    wire_.refuse = true;
    wire_.status = {net::ConnectionState::Closed,
                    "The server closed the connection (code 1012: the server is restarting).",
                    1012};
    ASSERT_TRUE(step_until(*runner_, [&] { return wire_.opened >= 3; })); // two refused tries
    EXPECT_FALSE(runner_->done());
    wire_.refuse = false;
    ASSERT_TRUE(
        step_until(*runner_, [&] { return wire_.status.state == net::ConnectionState::Open; }));
    EXPECT_EQ(std::get<proto::Hello>(wire_.sent.back()).resume_token, token);
    deliver(proto::Welcome{1, 7, token, 0});
    deliver(room_for(match_, 0, proto::Phase::Aiming)); // the shot never arrived: still due
    EXPECT_EQ(runner_->summary().resumes, 1);
    EXPECT_EQ(sent<proto::Shoot>().size(), 2u);
    EXPECT_FALSE(runner_->done());
    ASSERT_GE(notices.size(), 3u);
    EXPECT_EQ(notices.front(),
              "Connection lost: The server closed the connection (code 1012: the server is "
              "restarting). Resuming seat 0 in room ABCDEF for up to 5.0 s.");
    EXPECT_EQ(notices.back().rfind("Resumed seat 0 in room ABCDEF (try ", 0), 0u);
}

TEST_F(BotRunnerTest, AGameThatEndedWhileAwayCountsOnResume) {
    BotConfig config;
    config.reconnect = {0.001, 0.001, 5.0};
    start(config);
    const std::string token(32, 'f');
    deliver(proto::Welcome{1, 7, token, 0});
    deliver(room_for(match_, 1, proto::Phase::Moving));
    wire_.status = {net::ConnectionState::Closed, "lost", 0};
    ASSERT_TRUE(step_until(*runner_, [&] { return wire_.opened == 2; }));
    deliver(proto::Welcome{1, 7, token, 0});
    proto::RoomState over = room_for(match_, 1, proto::Phase::GameOver);
    over.winner = 1;
    over.scores = {40, 150};
    deliver(over);
    EXPECT_TRUE(runner_->done());
    const auto& summary = runner_->summary();
    EXPECT_TRUE(summary.finished) << summary.failure;
    EXPECT_EQ(summary.resumes, 1);
    EXPECT_EQ(summary.games, 1);
    EXPECT_EQ(summary.wins, 1);
    EXPECT_EQ(summary.scores, (std::vector<int>{40, 150}));
    EXPECT_EQ(summary.last_reason, "ended_while_away");
}

TEST_F(BotRunnerTest, GivesUpNamingTheSeatOnceTheResumeTimeIsOver) {
    BotConfig config;
    config.reconnect = {0.002, 0.008, 0.06};
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'f'), 0});
    deliver(room_for(match_, 1, proto::Phase::Aiming));
    wire_.refuse = true;
    wire_.status = {net::ConnectionState::Closed, "The connection to x:1 was lost (reset).", 0};
    ASSERT_TRUE(step_until(*runner_, [&] { return runner_->done(); }));
    const std::string failure = runner_->summary().failure;
    EXPECT_EQ(failure.rfind("Gave up resuming seat 1 in room ABCDEF after 0.", 0), 0u) << failure;
    EXPECT_NE(failure.find("; the last: Could not reach x:1: refused."), std::string::npos)
        << failure;
    EXPECT_GE(wire_.opened, 4);
}

TEST_F(BotRunnerTest, ASeatOpenedOnAnotherConnectionIsNotTakenBack) {
    start(BotConfig{});
    deliver(proto::Welcome{1, 7, std::string(32, 'f'), 0});
    deliver(room_for(match_, 1, proto::Phase::Aiming));
    wire_.status = {net::ConnectionState::Closed,
                    "The server closed the connection (code 4002: replaced).", 4002};
    runner_->step(0ms);
    EXPECT_EQ(runner_->summary().failure,
              "The server closed the connection (code 4002: replaced).");
    EXPECT_EQ(wire_.opened, 1);
}

TEST_F(BotRunnerTest, NoResumeBeforeARoomOrWhenTurnedOff) {
    BotConfig config;
    config.auto_resume = false;
    start(config);
    deliver(proto::Welcome{1, 7, std::string(32, 'f'), 0});
    deliver(room_for(match_, 1, proto::Phase::Aiming));
    wire_.status = {net::ConnectionState::Closed, "The connection to x:1 was lost (reset).", 0};
    runner_->step(0ms);
    EXPECT_EQ(runner_->summary().failure, "The connection to x:1 was lost (reset).");
    EXPECT_EQ(wire_.opened, 1);
}

TEST_F(BotRunnerTest, RefusedResumeIsAFailure) {
    start(BotConfig{});
    deliver(proto::Welcome{1, 7, std::string(32, 'f'), 0});
    runner_->drop();
    runner_->resume();
    deliver(proto::Error{"bad_token", "That seat is no longer yours."});
    EXPECT_EQ(runner_->summary().failure, "The server no longer holds the seat (bad_token: That "
                                          "seat is no longer yours.); the match is lost.");
}

TEST_F(BotRunnerTest, BadTokenAfterTheWelcomeEndsAnAutomaticResume) {
    BotConfig config;
    config.reconnect = {0.001, 0.001, 5.0};
    start(config);
    const std::string token(32, 'f');
    deliver(proto::Welcome{1, 7, token, 0});
    deliver(room_for(match_, 0, proto::Phase::Moving));
    wire_.status = {net::ConnectionState::Closed, "lost", 0};
    ASSERT_TRUE(step_until(*runner_, [&] { return wire_.opened == 2; }));
    deliver(proto::Welcome{1, 7, token, 0}); // the token is known, the room has closed
    deliver(proto::Error{"bad_token", "That room has closed."});
    EXPECT_TRUE(runner_->done());
    EXPECT_EQ(runner_->summary().failure, "The server no longer holds seat 0 in room ABCDEF "
                                          "(bad_token: That room has closed.); the match is lost.");
    EXPECT_EQ(runner_->summary().resumes, 0);
}

TEST_F(BotRunnerTest, CountsSnapshotsKeyframesAndGaps) {
    start(BotConfig{});
    proto::Snapshot snapshot;
    snapshot.keyframe = true;
    snapshot.seq = 10;
    deliver(snapshot);
    snapshot.keyframe = false;
    snapshot.seq = 11;
    deliver(snapshot);
    snapshot.seq = 13;
    deliver(snapshot);
    EXPECT_EQ(runner_->summary().snapshots, 3);
    EXPECT_EQ(runner_->summary().keyframes, 1);
    EXPECT_EQ(runner_->summary().seq_gaps, 1);
    EXPECT_EQ(runner_->summary().unrepaired_gaps, 0);
    deliver(proto::ShotResult{}); // no keyframe came after the gap
    EXPECT_EQ(runner_->summary().unrepaired_gaps, 1);
    snapshot.seq = 20;
    deliver(snapshot);
    snapshot.keyframe = true;
    snapshot.seq = 21;
    deliver(snapshot);
    deliver(proto::ShotResult{});
    EXPECT_EQ(runner_->summary().unrepaired_gaps, 1);
}

TEST(MatchView, RebuildsTheBoardScoresTurnAndBreaker) {
    auto match = rules::new_match(rules::RuleSet::Icf, rules::RulesConfig{}, PhysicsConfig{});
    match.bodies[3].pocketed = true;
    match.bodies[5].pos_px = {250.0, 260.0};
    proto::RoomState room;
    room.rule_set = proto::RuleSet::Icf;
    room.options = {9, 3, 0.0};
    room.seats.resize(2);
    room.seats[1].colour = proto::Colour::White;
    room.seats[0].colour = proto::Colour::Black;
    room.scores = {4, 7};
    room.dues = {1, 0};
    room.board_number = 2;
    room.turn = 17;
    room.to_play = 1;
    room.queen = {proto::QueenState::Pending, 1};
    for (const Body& body : match.bodies) {
        room.bodies.push_back(proto::to_board_body(body));
    }
    room.bodies.push_back(proto::BoardBody{19, BodyKind::Striker, {300, 520}, {}, false});
    const rules::MatchState state = match_state_from(room);
    EXPECT_EQ(state.rule_set, rules::RuleSet::Icf);
    EXPECT_EQ(state.config.target_points, 9);
    EXPECT_EQ(state.config.max_boards, 3);
    EXPECT_EQ(state.bodies.size(), 19u);
    EXPECT_TRUE(state.bodies[3].pocketed);
    EXPECT_EQ(state.bodies[5].pos_px, (Vec2{250.0, 260.0}));
    EXPECT_EQ(state.pocketed.size(), 1u);
    EXPECT_EQ(state.scores, (std::vector<int>{4, 7}));
    EXPECT_EQ(state.dues_owed, (std::vector<int>{1, 0}));
    EXPECT_EQ(state.board, 2);
    EXPECT_EQ(state.turn_number, 17);
    EXPECT_EQ(state.turn_seat, 1);
    EXPECT_EQ(state.breaker, 1);
    EXPECT_TRUE(state.break_done);
    EXPECT_EQ(state.queen.status, rules::QueenStatus::PendingCover);
    EXPECT_EQ(state.queen.seat, 1);
    EXPECT_EQ(state.phase, rules::Phase::AwaitingShot);
}

TEST(MatchView, FreshBoardHasNoBreakYet) {
    const auto match =
        rules::new_match(rules::RuleSet::Freestyle, rules::RulesConfig{}, PhysicsConfig{});
    proto::RoomState room;
    room.rule_set = proto::RuleSet::Freestyle;
    room.options = {120, 1, 20.0};
    for (const Body& body : match.bodies) {
        room.bodies.push_back(proto::to_board_body(body));
    }
    const rules::MatchState state = match_state_from(room);
    EXPECT_FALSE(state.break_done);
    EXPECT_EQ(state.config.freestyle.target, 120);
    EXPECT_DOUBLE_EQ(state.config.shot_clock_s, 20.0);
}

} // namespace
} // namespace carrom::bots
