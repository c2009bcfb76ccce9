// What a room tells its JournalSink: the match head, membership entries, seat holders' tokens,
// rematches; and the durability rule: nothing of a stroke is streamed before its entry is written.
#include "room/recording_journal.hpp"
#include "room/room_fixture.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace carrom::room {
namespace {

using testing::FakePeer;
using testing::RecordingJournal;
using testing::RoomTest;

class RoomJournalTest : public RoomTest {
protected:
    RoomJournalTest() : journaled_("JRNAAA", config(), clock_, counters_, nullptr, &sink_) {
        a_->token = "token-a";
        b_->token = "token-b";
    }

    void seat_both_journaled() {
        ASSERT_FALSE(journaled_.join(a_, proto::Role::Player));
        ASSERT_FALSE(journaled_.join(watcher_, proto::Role::Spectator));
        ASSERT_FALSE(journaled_.join(b_, proto::Role::Player));
    }

    template <class T> std::vector<T> events_of(const std::string& id) {
        std::vector<T> out;
        for (const auto& entry : sink_.journals.at(id).entries) {
            if (const auto* e = std::get_if<T>(&entry.event)) {
                out.push_back(*e);
            }
        }
        return out;
    }

    RecordingJournal sink_;
    Room journaled_;
};

TEST_F(RoomJournalTest, AStrokeIsNotStreamedUntilItsEntryIsWritten) {
    seat_both_journaled();
    a_->clear();
    b_->clear();
    watcher_->clear();
    journaled_.shoot(*a_, break_shot(0));
    ASSERT_EQ(sink_.waiting.size(), 1U);
    EXPECT_EQ(journaled_.phase(), proto::Phase::Moving);
    // The sink's answer wakes the room (or the pause, room_store_pause_test.cpp).
    EXPECT_EQ(journaled_.next_wake_ms(), clock_.now_ms() + kStorePauseAfterMs);
    clock_.advance_ms(5000);
    journaled_.tick();
    for (auto* peer : {a_.get(), b_.get(), watcher_.get()}) {
        EXPECT_TRUE(peer->all<proto::Snapshot>().empty());
        EXPECT_TRUE(peer->all<proto::ShotResult>().empty());
        EXPECT_TRUE(peer->events<proto::CollisionEvent>().empty());
    }
    journaled_.shoot(*a_, break_shot(0));
    EXPECT_EQ(a_->error_codes().back(), "in_motion");
    journaled_.journal_written("other", 0); // another match's answer changes nothing
    journaled_.journal_written(journaled_.match_id(), 1);
    EXPECT_TRUE(b_->all<proto::Snapshot>().empty());

    journaled_.journal_written(journaled_.match_id(), sink_.waiting[0].second);
    sink_.waiting.clear();
    ASSERT_EQ(b_->all<proto::Snapshot>().size(), 1U); // the first delta, at once
    EXPECT_FALSE(b_->all<proto::Snapshot>()[0].keyframe);
    ASSERT_TRUE(journaled_.next_wake_ms());
    while (journaled_.phase() == proto::Phase::Moving) {
        clock_.set_ms(*journaled_.next_wake_ms());
        journaled_.tick();
    }
    EXPECT_EQ(watcher_->all<proto::ShotResult>().size(), 1U);
    const auto strokes = events_of<proto::StrokeEntry>(journaled_.match_id());
    ASSERT_EQ(strokes.size(), 1U);
    EXPECT_EQ(strokes[0].turn, 0);
    EXPECT_EQ(strokes[0].seat, 0);
    EXPECT_EQ(strokes[0].shot.power, 25.0);
}

TEST_F(RoomJournalTest, TheHeadNamesTheSeatsAndTheHoldersTokensGoToTheSink) {
    seat_both_journaled();
    ASSERT_EQ(sink_.order.size(), 1U);
    const std::string id = sink_.order[0];
    const auto& created = sink_.journals.at(id).created;
    EXPECT_EQ(created.room_code, "JRNAAA");
    EXPECT_EQ(created.seats[0], (proto::JournalSeat{"Asha", false}));
    EXPECT_EQ(created.seats[1], (proto::JournalSeat{"Bo", false}));
    EXPECT_EQ(created.time_ms, clock_.now_ms()); // ManualClock: unix_ms() is now_ms()
    EXPECT_TRUE(created.rematch_of.empty());
    EXPECT_EQ((sink_.tokens.at({id, 0})), "token-a");
    EXPECT_EQ((sink_.tokens.at({id, 1})), "token-b");
    EXPECT_TRUE(sink_.journals.at(id).entries.empty()); // spectators are not journaled
}

TEST_F(RoomJournalTest, DropsReturnsAndALeaveAreJournaledInOrder) {
    seat_both_journaled();
    const std::string id = journaled_.match_id();
    journaled_.disconnected(*b_);
    auto b2 = std::make_shared<FakePeer>(2, "Bo");
    b2->token = "token-b";
    ASSERT_FALSE(journaled_.resume(b2));
    journaled_.leave(*a_); // a running game: a forfeit, then the leave
    const auto& entries = sink_.journals.at(id).entries;
    ASSERT_EQ(entries.size(), 4U);
    EXPECT_EQ(std::get<proto::SeatDroppedEntry>(entries[0].event).seat, 1);
    EXPECT_EQ(std::get<proto::SeatReturnedEntry>(entries[1].event).seat, 1);
    const auto& forfeit = std::get<proto::ForfeitEntry>(entries[2].event);
    EXPECT_EQ(forfeit.seat, 0);
    EXPECT_EQ(forfeit.reason, proto::ForfeitReason::Left);
    EXPECT_TRUE(forfeit.outcome.game_end);
    EXPECT_EQ(std::get<proto::SeatLeftEntry>(entries[3].event).seat, 0);
    EXPECT_EQ((sink_.tokens.at({id, 0})), ""); // the freed seat has no holder
    EXPECT_TRUE(sink_.abandoned_ids.empty());  // the game ended by the rules
}

TEST_F(RoomJournalTest, AnExpiredGraceForfeitsAndARoomLeftMidGameIsAbandoned) {
    {
        Room room("JRNBBB", config(), clock_, counters_, nullptr, &sink_);
        ASSERT_FALSE(room.join(a_, proto::Role::Player));
        ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<testing::ScriptedBrain>()));
        room.disconnected(*a_);
        clock_.advance_ms(60001);
        room.tick();
        const auto forfeits = events_of<proto::ForfeitEntry>(room.match_id());
        ASSERT_EQ(forfeits.size(), 1U);
        EXPECT_EQ(forfeits[0].reason, proto::ForfeitReason::GraceExpired);
    }
    EXPECT_TRUE(sink_.abandoned_ids.empty());
    {
        Room room("JRNCCC", config(), clock_, counters_, nullptr, &sink_);
        ASSERT_FALSE(room.join(a_, proto::Role::Player));
        ASSERT_FALSE(room.seat_bot("Bot", std::make_shared<testing::ScriptedBrain>()));
        ASSERT_EQ(sink_.order.size(), 2U);
    }
    ASSERT_EQ(sink_.abandoned_ids.size(), 1U);
    EXPECT_EQ(sink_.abandoned_ids[0], sink_.order[1]);
}

TEST_F(RoomJournalTest, ARematchClosesTheJournalAndStartsOneNamingIt) {
    seat_both_journaled();
    journaled_.disconnected(*b_);
    clock_.advance_ms(60001);
    journaled_.tick(); // b forfeits by grace: the game is over
    auto b2 = std::make_shared<FakePeer>(4, "Di");
    b2->token = "token-d";
    ASSERT_FALSE(journaled_.join(b2, proto::Role::Player));
    const std::string first = sink_.order[0];
    journaled_.rematch(*a_);
    journaled_.rematch(*b2);
    ASSERT_EQ(sink_.order.size(), 2U);
    const std::string second = sink_.order[1];
    EXPECT_EQ(journaled_.match_id(), second);
    const auto& old_entries = sink_.journals.at(first).entries;
    EXPECT_EQ(std::get<proto::SeatJoinedEntry>(old_entries[old_entries.size() - 2].event),
              (proto::SeatJoinedEntry{1, "Di", false}));
    EXPECT_EQ(std::get<proto::RematchEntry>(old_entries.back().event).next_match_id, second);
    const auto& created = sink_.journals.at(second).created;
    EXPECT_EQ(created.rematch_of, first);
    EXPECT_EQ(created.first_turn, journaled_.match().turn_number);
    EXPECT_EQ(created.rules.first_breaker, 1);
    EXPECT_EQ(created.seats[1].name, "Di");
    EXPECT_EQ((sink_.tokens.at({second, 1})), "token-d");
}

} // namespace
} // namespace carrom::room
