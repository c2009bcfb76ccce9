// MatchModel's HUD lines and sound cues that the browser client (web/js/match_model.js) gives
// the same: dues and boards named by team in doubles, simultaneous cues merged.
#include "carrom/client/match_model.hpp"
#include "client/match_model_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace carrom::client {
namespace {

std::vector<std::string> texts(const HudLog& log) {
    std::vector<std::string> out;
    for (const HudLine& line : log.all()) {
        out.push_back(line.text);
    }
    return out;
}

proto::ShotResult shot_result(int turn, int seat, std::vector<int> dues) {
    proto::ShotResult r;
    r.turn = turn;
    r.seat = seat;
    r.scores = std::vector<int>(dues.size(), 0);
    r.dues = std::move(dues);
    r.next_turn = turn + 1;
    r.next_seat = (seat + 1) % static_cast<int>(r.dues.size());
    return r;
}

TEST(MatchModelHud, DoublesDuesAreSaidOncePerTeamAndSetOnBothPartners) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::doubles_room(0), 0.0); // Ravi & Dee owe 1 due already
    m.handle(shot_result(4, 0, {1, 1, 1, 1}), 1.0);
    m.handle(proto::Event{proto::DueEvent{0, 1}}, 1.0);
    m.handle(proto::Event{proto::DueEvent{2, 1}}, 1.0); // the partner's copy: not said again
    EXPECT_EQ(m.view().seats[0].dues, 1);
    EXPECT_EQ(m.view().seats[2].dues, 1);
    EXPECT_EQ(m.view().seats[1].dues, 1);
    EXPECT_EQ(texts(m.log()),
              (std::vector<std::string>{
                  "Joined room ABC234",
                  "Asha & Cy owe 1 due: the next coin they pocket goes back to the centre"}));
    EXPECT_EQ(m.log().all().back().tone, Tone::Foul);
}

TEST(MatchModelHud, OneDueEventSetsTheWholeTeam) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::doubles_room(0), 0.0);
    m.handle(proto::Event{proto::DueEvent{3, 2}}, 1.0);
    EXPECT_EQ(m.view().seats[1].dues, 2);
    EXPECT_EQ(m.view().seats[3].dues, 2);
    EXPECT_EQ(m.view().seats[0].dues, 0);
    EXPECT_EQ(m.log().all().back().text,
              "Ravi & Dee owe 2 dues: the next coins they pocket go back to the centre");
}

TEST(MatchModelHud, TheSameDuesInTheNextStrokeAreSaidAgain) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::doubles_room(0), 0.0);
    m.handle(shot_result(4, 1, {0, 2, 0, 2}), 1.0);
    m.handle(proto::Event{proto::DueEvent{1, 2}}, 1.0);
    m.handle(proto::Event{proto::DueEvent{3, 2}}, 1.0);
    m.handle(shot_result(5, 3, {0, 2, 0, 2}), 2.0);
    m.handle(proto::Event{proto::DueEvent{1, 2}}, 2.0);
    m.handle(proto::Event{proto::DueEvent{3, 2}}, 2.0);
    // Said again: the line still shown moves to the newest place with the new time (HudLog shows
    // no line twice).
    EXPECT_EQ(texts(m.log()),
              (std::vector<std::string>{
                  "Joined room ABC234",
                  "Ravi & Dee owe 2 dues: the next coins they pocket go back to the centre"}));
    EXPECT_EQ(m.log().all().back().posted_s, 2.0);
}

TEST(MatchModelHud, OtherTeamsOrOtherDuesInOneStrokeAreEachSaid) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::doubles_room(0), 0.0);
    m.handle(shot_result(4, 0, {1, 0, 1, 0}), 1.0);
    m.handle(proto::Event{proto::DueEvent{0, 1}}, 1.0);
    m.handle(proto::Event{proto::DueEvent{1, 0}}, 1.0); // paid off: nothing to say
    m.handle(proto::Event{proto::DueEvent{2, 1}}, 1.0); // not right after its partner's: said
    m.handle(proto::Event{proto::DueEvent{2, 3}}, 1.0);
    // Each said (the second "owe 1 due" takes the first one's place: no line twice).
    EXPECT_EQ(texts(m.log()),
              (std::vector<std::string>{
                  "Joined room ABC234",
                  "Asha & Cy owe 1 due: the next coin they pocket goes back to the centre",
                  "Asha & Cy owe 3 dues: the next coins they pocket go back to the centre"}));
    EXPECT_EQ(m.view().seats[3].dues, 0);
    EXPECT_EQ(m.view().seats[0].dues, 3);
}

TEST(MatchModelHud, SinglesDuesNameTheSeat) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    m.handle(proto::Event{proto::DueEvent{0, 1}}, 1.0);
    m.handle(proto::Event{proto::DueEvent{1, 1}}, 1.0);
    EXPECT_EQ(texts(m.log()),
              (std::vector<std::string>{
                  "Joined room ABC234",
                  "Ana owes 1 due: the next coin Ana pockets goes back to the centre",
                  "Ben owes 1 due: the next coin Ben pockets goes back to the centre"}));
    EXPECT_EQ(m.view().seats[0].dues, 1);
}

TEST(MatchModelHud, BoardEndNamesTheWinningTeamInDoubles) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::doubles_room(2), 0.0);
    m.handle(proto::Event{proto::BoardEndEvent{2, 1, 3, {7, 6, 7, 6}}}, 1.0);
    EXPECT_EQ(m.log().all().back().text, "Board 2 to Ravi & Dee (+3)");
    EXPECT_EQ(m.log().all().back().tone, Tone::Good);
    EXPECT_EQ(m.view().seats[3].score, 6);
    EXPECT_EQ(m.view().phase, proto::Phase::BoardOver);
    m.handle(proto::Event{proto::BoardEndEvent{3, -1, 0, {7, 6, 7, 6}}}, 2.0);
    EXPECT_EQ(m.log().all().back().text, "Board 3 ends, no winner");
}

TEST(MatchModelHud, BoardEndNamesTheSeatInSingles) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(1), 0.0);
    m.handle(proto::Event{proto::BoardEndEvent{1, 0, 5, {8, 1}}}, 1.0);
    EXPECT_EQ(m.log().all().back().text, "Board 1 to Ana (+5)");
}

TEST(MatchModelHud, SimultaneousClicksOfABreakAreOneSoundTheLoudest) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(), 0.0);
    proto::Snapshot s;
    s.seq = 1;
    s.turn = 4;
    s.bodies = {{19, {300, 520}, {0, -600}}};
    m.handle(s, 1.0);
    // Two mirrored coins hit at one instant, a pocket at the same instant, a click 5 ms later.
    m.handle(proto::Event{proto::CollisionEvent{4, 0.1, 19, 1, 300.0}}, 1.0);
    m.handle(proto::Event{proto::CollisionEvent{4, 0.1, 19, 2, 900.0}}, 1.0);
    m.handle(proto::Event{proto::PocketEvent{4, 0.1, 1, 3}}, 1.0);
    m.handle(proto::Event{proto::CollisionEvent{4, 0.105, 1, 2, 100.0}}, 1.0);
    for (double t = 1.0; t < 2.0; t += 1.0 / 60.0) {
        m.render(t);
    }
    const std::vector<SoundCue> all = m.take_sounds();
    ASSERT_EQ(all.size(), 3u);
    EXPECT_EQ(all[0].kind, SoundKind::Click);
    EXPECT_DOUBLE_EQ(all[0].volume, loudness_from_impulse(900.0));
    EXPECT_EQ(all[1].kind, SoundKind::Pocket);
    EXPECT_EQ(all[2].kind, SoundKind::Click);
    EXPECT_DOUBLE_EQ(all[2].volume, loudness_from_impulse(100.0));
    EXPECT_EQ(all[1].time_s, all[0].time_s);
    EXPECT_NEAR(all[2].time_s - all[0].time_s, 0.005, 1e-9);
}

} // namespace
} // namespace carrom::client
