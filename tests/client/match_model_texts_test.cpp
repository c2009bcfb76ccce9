// What a player reads in the desktop client's model (the same words as web/js, tests/web/
// texts_test.mjs): a foul in the warning colour with what it cost, the missed shot clock's count,
// the forfeit line, the board summary card, the shot clock's countdown ticks.
#include "carrom/client/board_summary_text.hpp"
#include "carrom/client/match_model.hpp"
#include "client/match_model_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace carrom::client {
namespace {

using Said = std::vector<std::pair<std::string, Tone>>;

// The lines after "Joined room" / "Watching room".
Said said(const HudLog& log) {
    Said out;
    for (const HudLine& line : log.all()) {
        if (line.text.rfind("Joined room", 0) != 0 && line.text.rfind("Watching room", 0) != 0) {
            out.emplace_back(line.text, line.tone);
        }
    }
    return out;
}

proto::ShotResult stroke(int seat, std::vector<int> pocketed, std::vector<proto::Foul> fouls) {
    proto::ShotResult r;
    r.turn = 4;
    r.seat = seat;
    r.pocketed = std::move(pocketed);
    r.fouls = std::move(fouls);
    r.points = {0, 0};
    r.scores = {3, 1};
    r.dues = {0, 1};
    r.next_turn = 5;
    r.next_seat = 1 - seat;
    return r;
}

TEST(MatchModelTexts, ACleanPocketingIsGoodNews) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    m.handle(stroke(0, {2}, {}), 1.0);
    EXPECT_EQ(said(m.log()), (Said{{"Ana pocketed 1 white coin", Tone::Good}}));
}

TEST(MatchModelTexts, AFoulIsAWarningAndSaysWhatItCost) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    proto::ShotResult r = stroke(0, {2, kStrikerId},
                                 {{"striker_pocketed", "The striker went "
                                                       "into a pocket."}});
    r.returned = {2, 0};
    m.handle(r, 1.0);
    m.handle(proto::Event{proto::DueEvent{0, 1}}, 1.0);
    EXPECT_EQ(
        said(m.log()),
        (Said{{"Ana pocketed 1 white coin and the striker", Tone::Foul},
              {"Foul by Ana: The striker went into a pocket.", Tone::Foul},
              {"Cost: 1 white coin and the queen back to the centre", Tone::Foul},
              {"Ana owes 1 due: the next coin Ana pockets goes back to the centre", Tone::Foul}}));
}

TEST(MatchModelTexts, AMissedShotClockSaysHowManyMoreMissesLose) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    const std::string sentence = "The shot clock ran out; the turn passes. 2 more missed turns "
                                 "in a row lose the game.";
    m.handle(stroke(0, {}, {{"shot_clock_expired", sentence}}), 1.0);
    EXPECT_EQ(said(m.log()), (Said{{"Foul by Ana: " + sentence, Tone::Foul}}));
}

TEST(MatchModelTexts, FreestyleNamesStrokePointsAndNoBoardPoints) {
    MatchModel m{PhysicsConfig{}};
    proto::RoomState room = test::singles_room(0);
    room.rule_set = proto::RuleSet::Freestyle;
    m.handle(room, 0.0);
    proto::ShotResult r = stroke(0, {kStrikerId}, {{"striker_pocketed", "Striker."}});
    r.points = {-10, 0};
    m.handle(r, 1.0);
    m.handle(proto::Event{proto::BoardEndEvent{1, 1, 0, {0, 40}}}, 1.0);
    EXPECT_EQ(said(m.log()), (Said{{"Ana pocketed the striker (-10)", Tone::Foul},
                                   {"Foul by Ana: Striker.", Tone::Foul},
                                   {"Cost: 10 points", Tone::Foul},
                                   {"Board 1 to Ben", Tone::Good}}));
}

TEST(MatchModelTexts, ALeaveNamesWhoLeftAndWhoWinsFromTheReadersSide) {
    const std::vector<std::pair<int, std::pair<std::string, Tone>>> cases{
        {1, {"Ana left the match: you win by forfeit", Tone::Good}},
        {-1, {"Ana left the match: Ben wins by forfeit", Tone::Info}}};
    for (const auto& [you, line] : cases) {
        MatchModel m{PhysicsConfig{}};
        m.handle(test::singles_room(you), 0.0);
        proto::ShotResult r = stroke(0, {}, {{"forfeit", "A player forfeited."}});
        r.game_over = true;
        m.handle(r, 1.0);
        m.handle(proto::Event{proto::GameEndEvent{1, "left", {0, 0}, "forfeit"}}, 1.0);
        EXPECT_EQ(said(m.log()), (Said{line})) << you;
    }
    MatchModel late{PhysicsConfig{}};
    late.handle(test::singles_room(0), 0.0);
    late.handle(stroke(1, {}, {{"forfeit", "A player forfeited."}}), 1.0);
    late.handle(proto::Event{proto::GameEndEvent{0, "forfeit", {0, 0}, "forfeit"}}, 1.0);
    EXPECT_EQ(said(late.log()),
              (Said{{"Ben did not come back in time: you win by forfeit", Tone::Good}}));
}

TEST(MatchModelTexts, ABoardSummaryComesBeforeTheNextBoard) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    m.handle(proto::Event{proto::BoardEndEvent{1, 1, 3, {3, 4}}}, 20.0);
    proto::RoomState next = test::singles_room(0);
    next.board_number = 2;
    next.scores = {3, 4};
    next.seats[0].colour = proto::Colour::Black;
    next.seats[1].colour = proto::Colour::White;
    m.handle(next, 20.0);
    EXPECT_TRUE(m.board_summary_shown(20.0));
    EXPECT_EQ(board_summary_text(m.view()),
              (BoardSummaryText{"Ben won board 1", "+3 points. Score: you 3, Ben 4",
                                "Board 2: you play black"}));
    EXPECT_TRUE(m.board_summary_shown(20.0 + MatchModel::kBoardSummaryS - 0.1));
    EXPECT_FALSE(m.board_summary_shown(20.0 + MatchModel::kBoardSummaryS + 0.1));
    m.dismiss_board_summary();
    EXPECT_FALSE(m.board_summary_shown(21.0));
}

TEST(MatchModelTexts, ABoardThatEndsTheGameHasNoSummaryCard) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    m.handle(proto::Event{proto::BoardEndEvent{1, 0, 25, {25, 0}}}, 20.0);
    m.handle(proto::Event{proto::GameEndEvent{0, "score", {25, 0}, "target_points"}}, 20.0);
    EXPECT_FALSE(m.board_summary_shown(20.0));
}

TEST(MatchModelTexts, TheShotClockTicksOnceASecondInItsLastSecondsOnOurTurn) {
    // singles_room: the server's clock is 5'000'000 ms at local 0 s, the deadline 15 s later.
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    std::vector<int> ticks;
    for (int i = 0; i <= 400; ++i) {
        if (const auto tick = m.countdown_tick(i * 0.05)) {
            ticks.push_back(*tick);
        }
    }
    EXPECT_EQ(ticks, (std::vector<int>{5, 4, 3, 2, 1}));
    MatchModel theirs{PhysicsConfig{}};
    proto::RoomState room = test::singles_room(1); // seat 0 to play: not ours
    theirs.handle(room, 0.0);
    EXPECT_FALSE(theirs.countdown_tick(12.0));
}

} // namespace
} // namespace carrom::client
