// Emotes in a room (and room_state's aim_assist switch): broadcast to every member, per-seat rate
// limit (EmoteLimiter), spectators and strangers refused, never journaled, never touching the
// match.
#include "carrom/room/emote_limiter.hpp"

#include "room/recording_journal.hpp"
#include "room/room_fixture.hpp"

namespace carrom::room::testing {
namespace {

constexpr proto::EmoteMessage kWow{proto::Emote::Wow};

// --- EmoteLimiter on its own ---

TEST(EmoteLimiter, ABurstOfThreeIsAccepted) {
    EmoteLimiter limiter;
    EXPECT_TRUE(limiter.try_take(5000));
    EXPECT_TRUE(limiter.try_take(5000));
    EXPECT_TRUE(limiter.try_take(5000));
}

TEST(EmoteLimiter, TheFourthAtOnceIsRefused) {
    EmoteLimiter limiter;
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(limiter.try_take(5000));
    }
    EXPECT_FALSE(limiter.try_take(5000));
}

TEST(EmoteLimiter, OneMoreAfterEachInterval) {
    EmoteLimiter limiter;
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(limiter.try_take(5000));
    }
    EXPECT_FALSE(limiter.try_take(5000 + EmoteLimiter::kIntervalMs - 1));
    EXPECT_TRUE(limiter.try_take(5000 + EmoteLimiter::kIntervalMs));
    EXPECT_FALSE(limiter.try_take(5000 + EmoteLimiter::kIntervalMs));
}

TEST(EmoteLimiter, ARefusedEmoteCostsNothing) {
    EmoteLimiter limiter;
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(limiter.try_take(0));
    }
    for (int i = 0; i < 10; ++i) {
        EXPECT_FALSE(limiter.try_take(100));
    }
    EXPECT_TRUE(limiter.try_take(EmoteLimiter::kIntervalMs));
}

TEST(EmoteLimiter, AQuietSeatGetsItsWholeBurstBack) {
    EmoteLimiter limiter;
    for (int i = 0; i < 3; ++i) {
        ASSERT_TRUE(limiter.try_take(0));
    }
    const std::int64_t later = 3 * EmoteLimiter::kIntervalMs;
    EXPECT_TRUE(limiter.try_take(later));
    EXPECT_TRUE(limiter.try_take(later));
    EXPECT_TRUE(limiter.try_take(later));
    EXPECT_FALSE(limiter.try_take(later));
}

TEST(EmoteLimiter, OneEveryIntervalIsNeverRefused) {
    EmoteLimiter limiter;
    for (int i = 0; i < 50; ++i) {
        EXPECT_TRUE(limiter.try_take(i * EmoteLimiter::kIntervalMs)) << i;
    }
}

// --- in a room ---

TEST_F(RoomTest, AnEmoteReachesEveryMemberWithTheSendersSeat) {
    seat_both();
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    room_.emote(*b_, {proto::Emote::NiceShot});
    const proto::EmoteEvent expected{1, proto::Emote::NiceShot};
    for (const auto* peer : {a_.get(), b_.get(), watcher_.get()}) {
        const auto emotes = peer->events<proto::EmoteEvent>();
        ASSERT_EQ(emotes.size(), 1U) << peer->name();
        EXPECT_EQ(emotes[0], expected) << peer->name();
    }
    EXPECT_EQ(b_->error_codes().size(), 0U);
}

TEST_F(RoomTest, EmotesAreSentAsCues) {
    seat_both();
    a_->clear();
    room_.emote(*a_, kWow);
    ASSERT_EQ(a_->kinds.size(), 1U);
    EXPECT_EQ(a_->kinds[0], MessageKind::Cue);
}

TEST_F(RoomTest, TheFourthEmoteAtOnceIsTooFast) {
    seat_both();
    for (int i = 0; i < 4; ++i) {
        room_.emote(*a_, kWow);
    }
    EXPECT_EQ(b_->events<proto::EmoteEvent>().size(), 3U);
    EXPECT_EQ(a_->error_codes(), std::vector<std::string>{"emote_too_fast"});
}

TEST_F(RoomTest, TooFastNamesTheWaitInPlainWords) {
    seat_both();
    for (int i = 0; i < 4; ++i) {
        room_.emote(*a_, kWow);
    }
    const auto errors = a_->all<proto::Error>();
    ASSERT_EQ(errors.size(), 1U);
    EXPECT_EQ(errors[0].message, "Too many emotes; wait a moment before the next one.");
}

TEST_F(RoomTest, EachSeatHasItsOwnEmoteLimit) {
    seat_both();
    for (int i = 0; i < 3; ++i) {
        room_.emote(*a_, kWow);
    }
    room_.emote(*b_, kWow);
    EXPECT_TRUE(b_->error_codes().empty());
    EXPECT_EQ(a_->events<proto::EmoteEvent>().size(), 4U);
}

TEST_F(RoomTest, AnEmoteIsAllowedAgainAfterTheInterval) {
    seat_both();
    for (int i = 0; i < 4; ++i) {
        room_.emote(*a_, kWow);
    }
    clock_.advance_ms(EmoteLimiter::kIntervalMs);
    room_.emote(*a_, kWow);
    EXPECT_EQ(b_->events<proto::EmoteEvent>().size(), 4U);
    EXPECT_EQ(a_->error_codes().size(), 1U);
}

TEST_F(RoomTest, TooManyEmotesLeaveTheMatchAlone) {
    seat_both();
    const int turn = room_.match().turn_number;
    for (int i = 0; i < 20; ++i) {
        room_.emote(*a_, kWow);
    }
    EXPECT_EQ(a_->closed_with, 0);
    EXPECT_EQ(room_.seat_of(*a_), 0);
    room_.shoot(*a_, break_shot(turn));
    EXPECT_EQ(a_->last_error(), "emote_too_fast"); // the shot itself is accepted
    EXPECT_EQ(room_.phase(), proto::Phase::Moving);
}

TEST_F(RoomTest, SpectatorsCannotSendEmotes) {
    seat_both();
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    room_.emote(*watcher_, kWow);
    EXPECT_EQ(watcher_->last_error(), "spectator");
    EXPECT_TRUE(a_->events<proto::EmoteEvent>().empty());
}

TEST_F(RoomTest, StrangersCannotSendEmotes) {
    seat_both();
    auto stranger = std::make_shared<FakePeer>(8, "X");
    room_.emote(*stranger, kWow);
    EXPECT_EQ(stranger->last_error(), "not_in_room");
    EXPECT_TRUE(a_->events<proto::EmoteEvent>().empty());
}

TEST_F(RoomTest, NoEmoteBeforeTheGameStarts) {
    ASSERT_FALSE(room_.join(a_, proto::Role::Player));
    room_.emote(*a_, kWow);
    EXPECT_EQ(a_->last_error(), "wrong_phase");
    EXPECT_TRUE(a_->events<proto::EmoteEvent>().empty());
}

TEST_F(RoomTest, AnEmoteIsAllowedWhileTheShotPlays) {
    seat_both();
    room_.shoot(*a_, break_shot(room_.match().turn_number));
    ASSERT_EQ(room_.phase(), proto::Phase::Moving);
    room_.emote(*b_, {proto::Emote::Oops});
    EXPECT_EQ(a_->events<proto::EmoteEvent>().size(), 1U);
}

TEST_F(RoomTest, AnEmoteIsAllowedAfterTheGameEnds) {
    seat_both();
    room_.leave(*b_); // a forfeit: game over
    ASSERT_EQ(room_.phase(), proto::Phase::GameOver);
    room_.emote(*a_, {proto::Emote::GoodGame});
    EXPECT_EQ(a_->events<proto::EmoteEvent>().size(), 1U);
}

// RoomTest's room, with a journal.
class RoomEmoteJournalTest : public RoomTest {
protected:
    static RoomConfig journal_config() { return config(); }
};

TEST_F(RoomEmoteJournalTest, EmotesAreNotJournaled) {
    ManualClock clock;
    RoomCounters counters;
    RecordingJournal journal;
    Room room("ABCDEF", journal_config(), clock, counters, nullptr, &journal);
    auto a = std::make_shared<FakePeer>(1, "Asha");
    auto b = std::make_shared<FakePeer>(2, "Bo");
    ASSERT_FALSE(room.join(a, proto::Role::Player));
    ASSERT_FALSE(room.join(b, proto::Role::Player));
    ASSERT_EQ(journal.order.size(), 1U);
    const proto::MatchJournal& match = journal.journals[journal.order[0]];
    const std::size_t before = match.entries.size();
    room.emote(*a, {proto::Emote::GoodLuck});
    EXPECT_EQ(b->events<proto::EmoteEvent>().size(), 1U);
    EXPECT_EQ(match.entries.size(), before);
}

TEST_F(RoomTest, RoomStateAllowsAimAssistByDefault) {
    seat_both();
    EXPECT_TRUE(a_->last_room_state().aim_assist);
}

TEST(RoomAimAssist, ARoomWithoutAimAssistSaysSo) {
    ManualClock clock;
    RoomCounters counters;
    RoomConfig config;
    config.aim_assist = false;
    Room room("ABCDEF", config, clock, counters);
    auto a = std::make_shared<FakePeer>(1, "Asha");
    ASSERT_FALSE(room.join(a, proto::Role::Player));
    EXPECT_FALSE(a->last_room_state().aim_assist);
}

} // namespace
} // namespace carrom::room::testing
