// The desktop client's emotes: EmoteBoard (what shows, for how long, the mutes), the words of
// each emote (the web page's, web/js/emotes.js), and MatchModel taking the "emote" event and
// room_state's aim_assist.
#include "carrom/client/emote_board.hpp"
#include "carrom/client/match_model.hpp"
#include "client/match_model_support.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace carrom::client {
namespace {

using proto::Emote;

TEST(EmoteBoard, EveryEmoteHasTheWebPagesWords) {
    const std::vector<std::string> words{"Nice shot!", "Good game!", "Well played!", "Thanks!",
                                         "Good luck!", "Oops!",      "Wow!",         "Sorry!"};
    ASSERT_EQ(words.size(), proto::kEmoteNames.size());
    for (std::size_t i = 0; i < words.size(); ++i) {
        EXPECT_EQ(emote_text(proto::kEmoteNames[i].value), words[i]);
    }
}

TEST(EmoteBoard, AnEmoteShowsForItsTimeThenNot) {
    EmoteBoard b;
    EXPECT_TRUE(b.receive(1, Emote::Wow, 10.0));
    EXPECT_EQ(b.visible(10.0), (std::vector<ShownEmote>{{1, Emote::Wow}}));
    EXPECT_EQ(b.visible(10.0 + EmoteBoard::kShowS - 0.001).size(), 1U);
    EXPECT_TRUE(b.visible(10.0 + EmoteBoard::kShowS).empty());
}

TEST(EmoteBoard, ANewerEmoteOfTheSeatReplacesTheOlder) {
    EmoteBoard b;
    b.receive(0, Emote::Wow, 10.0);
    b.receive(0, Emote::Oops, 11.0);
    EXPECT_EQ(b.visible(11.0), (std::vector<ShownEmote>{{0, Emote::Oops}}));
}

TEST(EmoteBoard, SeatsShowInSeatOrder) {
    EmoteBoard b;
    b.receive(3, Emote::Wow, 10.0);
    b.receive(1, Emote::Oops, 10.0);
    EXPECT_EQ(b.visible(10.0), (std::vector<ShownEmote>{{1, Emote::Oops}, {3, Emote::Wow}}));
}

TEST(EmoteBoard, AMutedSeatShowsNothing) {
    EmoteBoard b;
    b.set_muted(1, true);
    EXPECT_FALSE(b.receive(1, Emote::Wow, 10.0));
    EXPECT_TRUE(b.visible(10.0).empty());
    EXPECT_EQ(b.received(), 1);
}

TEST(EmoteBoard, MutingHidesWhatTheSeatShowsNow) {
    EmoteBoard b;
    b.receive(1, Emote::Wow, 10.0);
    b.receive(2, Emote::Oops, 10.0);
    b.set_muted(1, true);
    EXPECT_EQ(b.visible(10.0), (std::vector<ShownEmote>{{2, Emote::Oops}}));
}

TEST(EmoteBoard, MuteAllCoversLaterSeatsUntilLifted) {
    EmoteBoard b;
    b.receive(0, Emote::Wow, 10.0);
    b.set_all_muted(true);
    EXPECT_TRUE(b.visible(10.0).empty());
    EXPECT_FALSE(b.receive(3, Emote::Wow, 11.0));
    b.set_all_muted(false);
    EXPECT_TRUE(b.receive(3, Emote::Wow, 12.0));
}

TEST(EmoteBoard, UnmutingShowsTheNextEmote) {
    EmoteBoard b;
    b.set_muted(1, true);
    b.set_muted(1, false);
    EXPECT_TRUE(b.receive(1, Emote::Sorry, 10.0));
}

TEST(MatchModelEmotes, AnEmoteEventShowsBesideItsSeat) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    m.handle(proto::Event{proto::EmoteEvent{1, Emote::GoodGame}}, 2.0);
    EXPECT_EQ(m.emotes().visible(2.0), (std::vector<ShownEmote>{{1, Emote::GoodGame}}));
}

TEST(MatchModelEmotes, AResetClearsTheEmotesButKeepsTheMutes) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    m.emotes().set_muted(0, true);
    m.handle(proto::Event{proto::EmoteEvent{1, Emote::Thanks}}, 1.0);
    m.reset();
    EXPECT_TRUE(m.emotes().visible(1.0).empty());
    EXPECT_TRUE(m.emotes().muted(0));
}

TEST(MatchModelEmotes, AnEmoteAddsNoHudLine) {
    MatchModel m{PhysicsConfig{}};
    m.handle(test::singles_room(0), 0.0);
    const std::size_t lines = m.log().all().size();
    m.handle(proto::Event{proto::EmoteEvent{1, Emote::Wow}}, 1.0);
    EXPECT_EQ(m.log().all().size(), lines);
}

TEST(MatchModelAimAssist, TheRoomStateSaysWhetherTheGuideIsAllowed) {
    MatchModel m{PhysicsConfig{}};
    proto::RoomState room = test::singles_room(0);
    m.handle(room, 0.0);
    EXPECT_TRUE(m.view().aim_assist);
    room.aim_assist = false;
    m.handle(room, 1.0);
    EXPECT_FALSE(m.view().aim_assist);
}

} // namespace
} // namespace carrom::client
