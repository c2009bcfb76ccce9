#include "carrom/client/match_model.hpp"
#include "client/match_model_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace carrom::client {
namespace {

proto::RoomState room(int you = 0) {
    return test::singles_room(you);
}

TEST(MatchModel, RoomStateFillsTheView) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 10.0);
    const MatchView& v = m.view();
    EXPECT_TRUE(v.in_room);
    EXPECT_EQ(v.code, "ABC234");
    ASSERT_EQ(v.seats.size(), 2u);
    EXPECT_EQ(v.seats[1].name, "Ben");
    EXPECT_EQ(v.seats[0].score, 3);
    EXPECT_EQ(v.seats[1].dues, 1);
    EXPECT_EQ(v.seats[1].colour, proto::Colour::Black);
    EXPECT_TRUE(m.my_turn());
    EXPECT_EQ(m.view_side(), rules::Side::Bottom);
    EXPECT_FALSE(m.spectator());
    const auto board = m.board_now();
    ASSERT_EQ(board.size(), 3u);
    EXPECT_TRUE(board[2].pocketed);
}

TEST(MatchModel, TopSeatSeesTheBoardTurned) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(1), 0.0);
    EXPECT_EQ(m.view_side(), rules::Side::Top);
    EXPECT_FALSE(m.my_turn());
    EXPECT_EQ(partner_of(m.view(), 1), -1); // singles: no partners
    EXPECT_EQ(team_of(m.view(), 1), 1);
    MatchModel spectator{PhysicsConfig{}};
    spectator.handle(room(-1), 0.0);
    EXPECT_TRUE(spectator.spectator());
    EXPECT_EQ(spectator.view_side(), rules::Side::Bottom);
}

using test::doubles_room;

TEST(MatchModel, FourSeatRoomStateGivesSidesTeamsAndTurnedViews) {
    const rules::Side expected[] = {rules::Side::Bottom, rules::Side::Right, rules::Side::Top,
                                    rules::Side::Left};
    for (int you = 0; you < 4; ++you) {
        MatchModel m{PhysicsConfig{}};
        m.handle(doubles_room(you), 1.0);
        const MatchView& v = m.view();
        ASSERT_EQ(v.seats.size(), 4u);
        EXPECT_EQ(m.view_side(), expected[you]) << you;
        EXPECT_EQ(m.my_turn(), you == 1) << you;
        for (int seat = 0; seat < 4; ++seat) {
            EXPECT_EQ(m.seat_side(seat), expected[seat]);
            EXPECT_EQ(team_of(v, seat), seat % 2);
            EXPECT_EQ(partner_of(v, seat), (seat + 2) % 4);
        }
    }
    MatchModel m{PhysicsConfig{}};
    m.handle(doubles_room(3), 1.0);
    const MatchView& v = m.view();
    EXPECT_EQ(v.seats[1].score, v.seats[3].score);
    EXPECT_EQ(v.seats[3].dues, 1);
    EXPECT_FALSE(v.seats[3].connected);
    EXPECT_EQ(team_seats(v, 0), (std::vector<int>{0, 2}));
    EXPECT_EQ(team_name(v, 0), "Asha & Cy");
    EXPECT_EQ(team_name(v, 1), "Ravi & Dee");
    // Partners play the same colour: each sees the same coins left.
    m.render(1.0);
    EXPECT_EQ(*m.coins_left(1), *m.coins_left(3));
    EXPECT_EQ(m.coins_left(1)->colour, proto::Colour::Black);
    MatchModel spectator{PhysicsConfig{}};
    spectator.handle(doubles_room(-1), 1.0);
    EXPECT_EQ(spectator.view_side(), rules::Side::Bottom);
}

TEST(MatchModel, DoublesGameEndNamesTheWinningTeam) {
    MatchModel m{PhysicsConfig{}};
    m.handle(doubles_room(2), 1.0);
    proto::GameEndEvent end;
    end.winner = 0; // team 0: seats 0 and 2
    end.reason = "score";
    end.scores = {25, 11, 25, 11};
    end.rule = "target_points";
    m.handle(proto::Event{end}, 2.0);
    ASSERT_TRUE(m.view().result.has_value());
    EXPECT_EQ(m.view().result->winner, 0);
    EXPECT_EQ(m.view().result->reason, "score");
    EXPECT_EQ(m.view().result->rule, "target_points");
    EXPECT_EQ(game_end_name(*m.view().result), "target_points");
    EXPECT_EQ(m.view().seats[2].score, 25);
    EXPECT_EQ(team_of(m.view(), m.view().you), m.view().result->winner);
}

TEST(MatchModel, ShotClockCountsDownByTheServersClock) {
    MatchModel m{PhysicsConfig{}};
    // Our clock says 10 s; the server's says 5000 s: the deadline is 15 s after the message.
    m.handle(room(), 10.0);
    EXPECT_NEAR(*m.shot_clock_left_s(10.0), 15.0, 1e-9);
    EXPECT_NEAR(*m.shot_clock_left_s(20.0), 5.0, 1e-9);
    EXPECT_DOUBLE_EQ(*m.shot_clock_left_s(40.0), 0.0);
}

TEST(MatchModel, PongRefinesTheServerClock) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 10.0); // one-way: the message took unknown time
    // A ping sent at 11.0 answered at 11.2 with server time 5'001'150 (the midpoint).
    m.server_clock().round_trip(5'001'150, 11.0, 11.2);
    EXPECT_NEAR(m.server_clock().server_now_ms(11.1), 5'001'150.0, 1e-6);
    EXPECT_NEAR(*m.server_clock().rtt_ms(), 200.0, 1e-9);
    EXPECT_NEAR(*m.shot_clock_left_s(11.1), 13.85, 1e-9);
}

TEST(MatchModel, TurnEventStartsAnotherTurn) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    const std::size_t said = m.log().all().size();
    m.handle(proto::Event{proto::TurnEvent{5, 1, 5'030'000, 5'010'000}}, 1.0);
    EXPECT_EQ(m.view().turn, 5);
    EXPECT_EQ(m.view().to_play, 1);
    EXPECT_FALSE(m.my_turn());
    EXPECT_NEAR(*m.shot_clock_left_s(1.0), 20.0, 1e-9);
    m.handle(proto::Event{proto::TurnEvent{6, 0, std::nullopt, 5'020'000}}, 2.0);
    EXPECT_TRUE(m.my_turn());
    EXPECT_FALSE(m.shot_clock_left_s(2.0).has_value());
    // The status line says whose turn it is ("Ben to play", "Your turn"): the log adds nothing.
    EXPECT_EQ(m.log().all().size(), said);
}

TEST(MatchModel, SnapshotsMoveTheBoardAndPocketsAnimate) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    proto::Snapshot s0;
    s0.seq = 1;
    s0.turn = 4;
    s0.t_s = 0.0;
    s0.bodies = {{19, {300, 520}, {0, -600}}, {1, {300, 265}, {0, 0}}};
    m.handle(s0, 1.0);
    EXPECT_EQ(m.view().phase, proto::Phase::Moving);
    proto::Snapshot s1 = s0;
    s1.seq = 2;
    s1.t_s = 0.5;
    s1.bodies = {{19, {300, 300}, {0, -100}}};
    s1.pocketed = {1};
    m.handle(s1, 1.5);
    const auto board = m.board_now();
    const auto striker =
        std::find_if(board.begin(), board.end(), [](const BodyState& b) { return b.id == 19; });
    ASSERT_NE(striker, board.end());
    EXPECT_EQ(striker->kind, BodyKind::Striker);
    EXPECT_EQ(striker->pos_px, (Vec2{300, 300}));
    const auto coin =
        std::find_if(board.begin(), board.end(), [](const BodyState& b) { return b.id == 1; });
    EXPECT_TRUE(coin->pocketed);
    EXPECT_EQ(coin->pos_px, (Vec2{300, 265})); // its last place, for the fall animation
    EXPECT_TRUE(m.animating());
    // Duplicates are dropped.
    m.handle(s1, 1.6);
    EXPECT_EQ(m.buffer().newest_seq(), 3u);
}

TEST(MatchModel, ShotTimeNamesTheShotATimeFallsInAndTheTimeSinceItStarted) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    EXPECT_EQ(m.shot_time(100.0).turn, -1); // the board at rest starts no shot
    proto::Snapshot s;
    s.seq = 1;
    s.turn = 4;
    s.t_s = 0.1; // the shot's first snapshot to arrive
    s.bodies = {{19, {300, 520}, {0, -600}}};
    m.handle(s, 1.0);
    s.seq = 2;
    s.t_s = 0.5;
    m.handle(s, 1.4);
    const MatchModel::ShotTime late = m.shot_time(100.0);
    EXPECT_EQ(late.turn, 4);
    const double start4 = 100.0 - late.t_s; // turn 4's t = 0 on the continuous timeline
    EXPECT_EQ(m.shot_time(start4 - 1e-6).turn, -1);
    EXPECT_EQ(m.shot_time(start4 + 0.25).turn, 4);
    EXPECT_NEAR(m.shot_time(start4 + 0.25).t_s, 0.25, 1e-9);
    // The next shot: times from its start on belong to it, earlier ones still to turn 4.
    s.seq = 3;
    s.turn = 5;
    s.t_s = 0.0;
    m.handle(s, 10.0);
    const double start5 = 100.0 - m.shot_time(100.0).t_s;
    EXPECT_EQ(m.shot_time(100.0).turn, 5);
    EXPECT_GT(start5, start4 + 0.5);
    EXPECT_EQ(m.shot_time(start5 - 1e-6).turn, 4);
    EXPECT_NEAR(m.shot_time(start5 - 1e-6).t_s, start5 - 1e-6 - start4, 1e-9);
}

TEST(MatchModel, PhysicsEventsBecomeSoundsWhenTheirTimeIsRendered) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    // The event arrives before the shot's first snapshot: it waits for it.
    m.handle(proto::Event{proto::CollisionEvent{4, 0.1, 19, 1, 900.0}}, 1.0);
    m.handle(proto::Event{proto::PocketEvent{4, 0.2, 1, 3}}, 1.0);
    m.handle(proto::Event{proto::CushionEvent{4, 0.3, 19, 2, 1.0}}, 1.0); // too soft to hear
    proto::Snapshot s0;
    s0.seq = 1;
    s0.turn = 4;
    s0.bodies = {{19, {300, 520}, {0, -600}}};
    m.handle(s0, 1.0);
    m.render(1.05);
    EXPECT_TRUE(m.take_sounds().empty());
    std::vector<SoundCue> all;
    for (double t = 1.0; t < 2.0; t += 1.0 / 60.0) {
        m.render(t);
        for (const SoundCue& c : m.take_sounds()) {
            all.push_back(c);
        }
    }
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].kind, SoundKind::Click);
    EXPECT_NEAR(all[0].volume, loudness_from_impulse(900.0), 1e-12);
    EXPECT_EQ(all[1].kind, SoundKind::Pocket);
}

TEST(MatchModel, AShotLongAfterTheJoinKeyframeSoundsWhenItIsRendered) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    // The join keyframe: turn 4 at rest, t = 0. The turn's shot starts 5 s later.
    proto::Snapshot join;
    join.seq = 1;
    join.turn = 4;
    join.keyframe = true;
    join.bodies = {{19, {300, 520}, {}}};
    m.handle(join, 0.01);
    for (double t = 0.0; t < 5.0; t += 1.0 / 60.0) {
        m.render(t);
    }
    m.handle(proto::Event{proto::CollisionEvent{4, 0.1, 19, 1, 900.0}}, 5.12);
    m.handle(proto::Event{proto::PocketEvent{4, 0.5, 1, 3}}, 5.52);
    std::vector<SoundCue> all;
    std::int64_t seq = 2;
    for (int k = 0; k <= 60; ++k) {
        const double t = k / 60.0;
        proto::Snapshot s;
        s.seq = seq++;
        s.turn = 4;
        s.t_s = t;
        s.bodies = {{19, {300, 520 - 600 * t}, {0, -600}}};
        m.handle(s, 5.02 + t);
        m.render(5.025 + t);
        for (const SoundCue& c : m.take_sounds()) {
            all.push_back(c);
        }
    }
    for (int k = 1; k <= 30; ++k) {
        m.render(6.02 + k / 60.0);
        for (const SoundCue& c : m.take_sounds()) {
            all.push_back(c);
        }
    }
    ASSERT_EQ(all.size(), 2u); // none dropped as late
    EXPECT_EQ(all[0].kind, SoundKind::Click);
    EXPECT_EQ(all[1].kind, SoundKind::Pocket);
    EXPECT_NEAR(all[1].time_s - all[0].time_s, 0.4, 1e-9);
}

TEST(MatchModel, ShotResultUpdatesScoresAndSaysWhatHappened) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    proto::ShotResult r;
    r.turn = 4;
    r.seat = 0;
    r.pocketed = {2, 0};
    r.scores = {5, 1};
    r.dues = {0, 0};
    r.queen = {proto::QueenState::Pending, 0};
    r.extra_turn = true;
    r.next_turn = 5;
    r.next_seat = 0;
    m.handle(r, 1.0);
    EXPECT_EQ(m.view().seats[0].score, 5);
    EXPECT_EQ(m.view().seats[1].dues, 0);
    EXPECT_EQ(m.view().queen.state, proto::QueenState::Pending);
    EXPECT_EQ(m.view().turn, 5);
    const auto lines = m.log().visible(1.0);
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[lines.size() - 2].text, "Ana pocketed 1 white coin and the queen");
    EXPECT_EQ(lines.back().text, "Ana plays again");
}

TEST(MatchModel, FoulsDuesQueenAndDropsAreTold) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    proto::ShotResult foul;
    foul.turn = 4;
    foul.seat = 1;
    foul.fouls = {{"striker_pocketed", "The striker went in."}};
    foul.next_turn = 5;
    m.handle(foul, 1.0);
    EXPECT_EQ(m.log().all().back().text, "Foul by Ben: The striker went in.");
    EXPECT_EQ(m.log().all().back().tone, Tone::Foul);
    const std::size_t said = m.log().all().size();
    m.handle(proto::Event{proto::FoulEvent{1, "striker_pocketed", "The striker went in."}}, 1.0);
    EXPECT_EQ(m.log().all().size(), said); // said with its shot_result
    m.handle(proto::Event{proto::DueEvent{1, 2}}, 1.0);
    EXPECT_EQ(m.view().seats[1].dues, 2);
    EXPECT_EQ(m.log().all().back().text,
              "Ben owes 2 dues: the next coins Ben pockets go back to the centre");
    m.handle(proto::Event{proto::QueenEvent{{proto::QueenState::Covered, 0}}}, 1.0);
    EXPECT_EQ(m.log().all().back().text, "Ana covered the queen");
    m.handle(proto::Event{proto::PlayerDroppedEvent{1, 5'060'000, 5'000'000}}, 1.0);
    EXPECT_FALSE(m.view().seats[1].connected);
    EXPECT_EQ(m.log().all().back().text, "Ben lost the connection; they have 60 s to come back");
    m.handle(proto::Event{proto::PlayerReturnedEvent{1}}, 2.0);
    EXPECT_TRUE(m.view().seats[1].connected);
}

TEST(MatchModel, APauseForTheStoreIsSaidThenThatTheMatchGoesOn) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    const std::string message = "The server cannot save the last stroke because its database "
                                "does not answer; the match goes on when it is back.";
    m.handle(proto::Event{proto::PausedEvent{"store", message}}, 1.0);
    EXPECT_EQ(m.log().all().back().text, message);
    EXPECT_EQ(m.log().all().back().tone, Tone::Error);
    m.handle(proto::Event{proto::ResumedEvent{}}, 2.0);
    EXPECT_EQ(m.log().all().back().text, "The match goes on");
    EXPECT_EQ(m.log().all().back().tone, Tone::Info);
}

TEST(MatchModel, OpponentAimIsShownLive) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(1), 0.0); // we are seat 1; seat 0 aims
    m.handle(proto::Event{proto::AimEvent{0, 4, 222.0}}, 1.0);
    EXPECT_EQ(m.view().aim_x_px, 222.0);
    m.handle(proto::Event{proto::AimEvent{0, 3, 111.0}}, 1.0); // an old turn's: ignored
    EXPECT_EQ(m.view().aim_x_px, 222.0);
}

TEST(MatchModel, ErrorsAreSaidInPlainWords) {
    MatchModel m{PhysicsConfig{}};
    m.handle(proto::Error{"room_not_found", "No room has code ZZZZZZ."}, 0.0);
    EXPECT_EQ(m.log().all().back().text,
              "There is no room with that code. Check the code and try again.");
    EXPECT_EQ(m.log().all().back().tone, Tone::Error);
    m.handle(proto::Error{"something_new", "A new problem."}, 0.0);
    EXPECT_EQ(m.log().all().back().text, "A new problem.");
}

TEST(MatchModel, GameEndKeepsWhoWonWhyAndTheScores) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    EXPECT_FALSE(m.view().result.has_value());
    m.handle(proto::Event{proto::GameEndEvent{1, "clock", {0, 0}}}, 1.0);
    EXPECT_EQ(m.view().phase, proto::Phase::GameOver);
    EXPECT_EQ(m.view().winner, 1);
    EXPECT_EQ(m.view().seats[0].score, 0);
    ASSERT_TRUE(m.view().result.has_value());
    EXPECT_EQ(m.view().result->winner, 1);
    EXPECT_EQ(m.view().result->reason, "clock");
    EXPECT_EQ(m.view().result->rule, ""); // a server that sends no rule
    EXPECT_EQ(game_end_name(*m.view().result), "clock");
    EXPECT_EQ(m.view().result->scores, (std::vector<int>{0, 0}));
    EXPECT_EQ(m.view().result->names, (std::vector<std::string>{"Ana", "Ben"}));
    // The room state that follows keeps the reason.
    proto::RoomState over = room();
    over.phase = proto::Phase::GameOver;
    over.winner = 1;
    over.scores = {0, 0};
    m.handle(over, 1.1);
    ASSERT_TRUE(m.view().result.has_value());
    EXPECT_EQ(m.view().result->reason, "clock");
    // Ben leaves: his seat empties, his name stays with the result.
    over.seats[1] = proto::SeatInfo{};
    m.handle(over, 1.2);
    EXPECT_EQ(m.seat_name(1), "Seat 2");
    EXPECT_EQ(player_name_at_end(m.view(), 1), "Ben");
    // A rematch starts a new game: the result is gone.
    m.handle(room(), 2.0);
    EXPECT_FALSE(m.view().result.has_value());
}

TEST(MatchModel, ARoomThatIsAlreadyOverHasAResultWithoutAReason) {
    MatchModel m{PhysicsConfig{}};
    proto::RoomState over = room(-1);
    over.phase = proto::Phase::GameOver;
    over.winner = 0;
    over.scores = {25, 7};
    m.handle(over, 0.0);
    ASSERT_TRUE(m.view().result.has_value());
    EXPECT_EQ(m.view().result->winner, 0);
    EXPECT_EQ(m.view().result->reason, "");
    EXPECT_EQ(m.view().result->scores, (std::vector<int>{25, 7}));
    EXPECT_EQ(m.view().result->names, (std::vector<std::string>{"Ana", "Ben"}));
}

TEST(MatchModel, CoinsLeftFollowTheDrawnBoard) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0); // the queen and black 1 on the board, white 2 pocketed
    m.render(0.0);
    EXPECT_EQ(m.coins_on_board(), (CoinsOnBoard{0, 1, true}));
    EXPECT_EQ(m.coins_left(0), (SeatCoins{proto::Colour::White, 0, true}));
    EXPECT_EQ(m.coins_left(1), (SeatCoins{proto::Colour::Black, 1, true}));
    EXPECT_EQ(m.coins_left(2), std::nullopt);
    // Black 1 goes in during a shot: it counts as gone from the frame it starts falling.
    proto::Snapshot s0;
    s0.seq = 1;
    s0.turn = 4;
    s0.t_s = 0.0;
    s0.bodies = {{19, {300, 520}, {0, -600}}, {1, {300, 265}, {0, -300}}};
    m.handle(s0, 1.0);
    proto::Snapshot s1 = s0;
    s1.seq = 2;
    s1.t_s = 0.5;
    s1.bodies = {{19, {300, 300}, {0, 0}}};
    s1.pocketed = {1};
    m.handle(s1, 1.5);
    m.render(1.0);
    EXPECT_EQ(m.coins_left(1), (SeatCoins{proto::Colour::Black, 1, true})); // not drawn yet
    m.render(3.0);
    EXPECT_EQ(m.coins_left(1), (SeatCoins{proto::Colour::Black, 0, true}));
    // A keyframe that puts it back (a foul) brings it back.
    m.handle(room(), 4.0);
    m.render(6.0);
    EXPECT_EQ(m.coins_left(1), (SeatCoins{proto::Colour::Black, 1, true}));
}

TEST(MatchModel, FreestyleSeatsBothCountEveryCoin) {
    MatchModel m{PhysicsConfig{}};
    proto::RoomState r = room();
    r.rule_set = proto::RuleSet::Freestyle;
    r.seats[0].colour = proto::Colour::None;
    r.seats[1].colour = proto::Colour::None;
    r.bodies.push_back({3, BodyKind::White, {330, 282}, {}, false});
    m.handle(r, 0.0);
    m.render(0.0);
    EXPECT_EQ(m.coins_left(0), (SeatCoins{proto::Colour::None, 2, true}));
    EXPECT_EQ(m.coins_left(1), (SeatCoins{proto::Colour::None, 2, true}));
}

TEST(MatchModel, AnotherRoomResetsTheBoard) {
    MatchModel m{PhysicsConfig{}};
    m.handle(room(), 0.0);
    proto::RoomState other = room();
    other.code = "XYZ789";
    other.bodies = {{0, BodyKind::Queen, {300, 300}, {}, false}};
    m.handle(other, 1.0);
    EXPECT_EQ(m.view().code, "XYZ789");
    EXPECT_EQ(m.board_now().size(), 1u);
}

} // namespace
} // namespace carrom::client
