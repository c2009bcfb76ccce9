// The journal a room writes through its JournalSink replays clean (proto::replay): a whole
// bot-vs-bot game with strokes, a shot clock expiry and the game's end. No FakePeer here (its
// codec and the replay's scene JSON cannot share a translation unit).
#include "room/recording_journal.hpp"
#include "room/spread_brain.hpp"

#include "carrom/proto/journal_replay.hpp"
#include "carrom/room/room.hpp"
#include "carrom/rules/state_hash.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>

namespace carrom::room {
namespace {

using testing::RecordingJournal;
using testing::SpreadBrain;

// Runs the room until its game is over: bots shoot, the sink confirms, streams play out. The
// shot clock runs out once, on the turn `skip_turn`.
int play_game(Room& room, ManualClock& clock, RecordingJournal& sink, int skip_turn) {
    int strokes = 0;
    for (int step = 0; step < 1000000 && room.match().phase != rules::Phase::GameOver; ++step) {
        if (room.phase() == proto::Phase::Moving) {
            sink.confirm_all(room);
            const auto wake = room.next_wake_ms();
            EXPECT_TRUE(wake);
            if (!wake) {
                break;
            }
            clock.set_ms(std::max(clock.now_ms(), *wake));
            room.tick();
            continue;
        }
        auto turn = room.take_bot_turn();
        if (!turn) {
            room.tick();
            continue;
        }
        if (turn->turn == skip_turn) {
            clock.set_ms(*room.next_wake_ms()); // the bot does not shoot: the clock runs out
            room.tick();
            continue;
        }
        // A placement the rules refuse is played as the nearest legal shot: every bot turn
        // plays a stroke.
        const Shot shot = turn->brain->choose_shot(turn->state, turn->seat, {});
        const BotShotOutcome outcome = room.bot_shoot(turn->seat, turn->turn, shot);
        EXPECT_FALSE(outcome.refused) << outcome.refused->message;
        strokes += outcome.refused ? 0 : 1;
    }
    EXPECT_EQ(room.match().phase, rules::Phase::GameOver)
        << "turn " << room.match().turn_number << " phase " << static_cast<int>(room.phase())
        << " seat " << room.match().turn_seat << " scores " << room.match().scores[0] << "/"
        << room.match().scores[1];
    return strokes;
}

TEST(RoomJournal, ABotGameJournalReplaysClean) {
    ManualClock clock;
    RoomCounters counters;
    RecordingJournal sink;
    RoomConfig config;
    config.rule_set = proto::RuleSet::Freestyle;
    config.rules.freestyle.target = 60;
    config.rules.shot_clock_s = 20.0;
    config.server_version = "9.9.9";
    Room room("RMJAAA", config, clock, counters, nullptr, &sink);
    ASSERT_FALSE(room.seat_bot("Bot (a)", std::make_shared<SpreadBrain>()));
    ASSERT_FALSE(room.seat_bot("Bot (b)", std::make_shared<SpreadBrain>()));
    ASSERT_EQ(sink.order.size(), 1U);
    EXPECT_EQ(room.match_id(), sink.order[0]);
    const int strokes = play_game(room, clock, sink, 3);
    ASSERT_EQ(room.match().phase, rules::Phase::GameOver) << strokes << " strokes";
    EXPECT_TRUE(sink.waiting.empty());

    const proto::MatchJournal& journal = sink.journals.at(room.match_id());
    EXPECT_EQ(journal.created.room_code, "RMJAAA");
    EXPECT_EQ(journal.created.rule_set, rules::RuleSet::Freestyle);
    EXPECT_EQ(journal.created.versions.server, "9.9.9");
    EXPECT_EQ(journal.created.first_turn, 0);
    ASSERT_EQ(journal.created.seats.size(), 2U);
    EXPECT_EQ(journal.created.seats[1], (proto::JournalSeat{"Bot (b)", true}));
    int journaled_strokes = 0;
    int expiries = 0;
    for (const auto& entry : journal.entries) {
        journaled_strokes += std::holds_alternative<proto::StrokeEntry>(entry.event) ? 1 : 0;
        expiries += std::holds_alternative<proto::ClockExpiredEntry>(entry.event) ? 1 : 0;
    }
    EXPECT_EQ(journaled_strokes, strokes);
    EXPECT_EQ(expiries, 1);
    const auto& last = journal.entries.back().event;
    ASSERT_NE(proto::outcome_of(last), nullptr);
    EXPECT_TRUE(proto::outcome_of(last)->game_end);

    const proto::ReplayResult replayed = proto::replay(journal);
    EXPECT_TRUE(replayed.ok()) << replayed.mismatches << " mismatches";
    EXPECT_EQ(replayed.steps.size(), journal.entries.size());
    EXPECT_EQ(rules::hash_match_state(replayed.state), rules::hash_match_state(room.match()));
}

TEST(RoomJournal, ARoomWithoutASinkPlaysTheSameGame) {
    ManualClock clock_a;
    ManualClock clock_b;
    RoomCounters counters;
    RecordingJournal sink;
    RecordingJournal unused;
    RoomConfig config;
    config.rule_set = proto::RuleSet::Freestyle;
    config.rules.freestyle.target = 60;
    Room journaled("RMJBBB", config, clock_a, counters, nullptr, &sink);
    Room plain("RMJCCC", config, clock_b, counters);
    for (Room* room : {&journaled, &plain}) {
        ASSERT_FALSE(room->seat_bot("A", std::make_shared<SpreadBrain>()));
        ASSERT_FALSE(room->seat_bot("B", std::make_shared<SpreadBrain>()));
    }
    play_game(journaled, clock_a, sink, -1);
    play_game(plain, clock_b, unused, -1);
    EXPECT_TRUE(plain.match_id().empty());
    EXPECT_EQ(rules::hash_match_state(journaled.match()), rules::hash_match_state(plain.match()));
}

} // namespace
} // namespace carrom::room
