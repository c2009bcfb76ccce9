// Room::restore: an unfinished match rebuilt from the journal its room wrote (a server restart).
// A player and a bot play part of a game; a new room restored from the journal holds the same
// state, the player's seat dropped with a new grace period, the bot thinking again; the player
// resumes, the game plays to its end and the whole journal replays clean.
#include "room/fake_peer.hpp"
#include "room/recording_journal.hpp"
#include "room/spread_brain.hpp"

#include "carrom/proto/journal_replay.hpp"
#include "carrom/room/room.hpp"
#include "carrom/rules/state_hash.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

namespace carrom::room {
namespace {

using testing::FakePeer;
using testing::RecordingJournal;
using testing::SpreadBrain;

RoomConfig restore_config() {
    RoomConfig config;
    config.rule_set = proto::RuleSet::Freestyle;
    config.rules.freestyle.target = 60;
    config.rules.shot_clock_s = 20.0;
    config.grace_s = 30.0;
    return config;
}

// Plays until the game is over or `inputs` strokes were played: the player at seat 0 (through
// its peer, shots from its own SpreadBrain) against the bot at seat 1. Returns the strokes.
int play(Room& room, ManualClock& clock, RecordingJournal& sink, FakePeer& player,
         SpreadBrain& hand, int inputs) {
    int strokes = 0;
    for (int step = 0; step < 1000000 && room.match().phase != rules::Phase::GameOver &&
                       (strokes < inputs || room.phase() == proto::Phase::Moving);
         ++step) {
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
        const rules::MatchState& state = room.match();
        for (int attempt = 0; attempt < 20 && room.phase() != proto::Phase::Moving; ++attempt) {
            if (state.turn_seat == 0) {
                const Shot shot = hand.choose_shot(state, 0, {});
                room.shoot(player, {state.turn_number, shot.x_px, shot.angle_rad, shot.power});
            } else {
                auto turn = room.take_bot_turn();
                const BotTurn t = turn ? *turn : BotTurn{};
                if (!turn) {
                    ADD_FAILURE() << "no bot turn at turn " << state.turn_number;
                    return strokes;
                }
                const Shot shot = t.brain->choose_shot(t.state, t.seat, {});
                if (room.bot_shoot(t.seat, t.turn, shot).refused) {
                    continue;
                }
            }
        }
        EXPECT_EQ(room.phase(), proto::Phase::Moving) << "no stroke accepted";
        ++strokes;
    }
    return strokes;
}

class RoomRestore : public ::testing::Test {
protected:
    RoomRestore() : original_("RSTAAA", restore_config(), clock_, counters_, nullptr, &sink_) {
        asha_->token = "token-of-asha";
        EXPECT_FALSE(original_.join(asha_, proto::Role::Player));
        EXPECT_FALSE(original_.seat_bot("Bot (medium)", std::make_shared<SpreadBrain>()));
    }

    const proto::MatchJournal& journal() const { return sink_.journals.at(original_.match_id()); }

    ManualClock clock_;
    RoomCounters counters_;
    RecordingJournal sink_;
    std::shared_ptr<FakePeer> asha_ = std::make_shared<FakePeer>(1, "Asha");
    SpreadBrain hand_;
    Room original_;
};

TEST_F(RoomRestore, ThePlayerResumesAndTheGameEndsWithAJournalThatReplaysClean) {
    ASSERT_EQ(play(original_, clock_, sink_, *asha_, hand_, 5), 5);
    ASSERT_NE(original_.match().phase, rules::Phase::GameOver);
    const proto::MatchJournal before = journal();
    const std::string id = original_.match_id();

    // The new process: its own sink holds what the store had.
    ManualClock clock(clock_.now_ms() + 5000);
    RoomCounters counters;
    RecordingJournal sink;
    sink.journals[id] = before;
    Room room("RSTAAA", restore_config(), clock, counters, nullptr, &sink);
    auto bot = std::make_shared<SpreadBrain>();
    ASSERT_EQ(room.restore(before, {RestoredSeat{7, nullptr}, RestoredSeat{-1, bot}}),
              std::nullopt);

    EXPECT_EQ(rules::hash_match_state(room.match()), rules::hash_match_state(original_.match()));
    EXPECT_EQ(room.match_id(), id);
    EXPECT_EQ(room.phase(), proto::Phase::Aiming);
    EXPECT_EQ(counters.matches.load(), 1);
    const proto::RoomState state = room.room_state(-1);
    ASSERT_EQ(state.seats.size(), 2U);
    EXPECT_EQ(state.seats[0].name, "Asha");
    EXPECT_FALSE(state.seats[0].connected);
    EXPECT_EQ(state.seats[1].name, "Bot (medium)");
    EXPECT_TRUE(state.seats[1].bot);
    EXPECT_TRUE(state.seats[1].connected);
    EXPECT_EQ(state.turn, original_.match().turn_number);
    // The shot clock starts again now (20 s), the grace period too (30 s): the clock comes first.
    ASSERT_TRUE(state.shot_clock_deadline_ms);
    EXPECT_EQ(*state.shot_clock_deadline_ms, clock.now_ms() + 20000);
    // The drop is journaled after the old entries; the stored token is left alone.
    ASSERT_EQ(sink.journals[id].entries.size(), before.entries.size() + 1);
    EXPECT_EQ(sink.journals[id].entries.back().event,
              proto::JournalEvent{proto::SeatDroppedEntry{0}});
    EXPECT_TRUE(sink.tokens.empty());

    // Asha comes back (player id 7 in the new process) and gets her seat, the board at rest.
    auto back = std::make_shared<FakePeer>(7, "Asha");
    back->token = "token-of-asha";
    ASSERT_EQ(room.resume(back), std::nullopt);
    EXPECT_EQ(back->last_room_state().you, 0);
    EXPECT_TRUE(back->last_room_state().seats[0].connected);
    EXPECT_FALSE(back->all<proto::Snapshot>().empty());
    EXPECT_EQ((sink.tokens[{id, 0}]), "token-of-asha");
    EXPECT_EQ(sink.journals[id].entries.back().event,
              proto::JournalEvent{proto::SeatReturnedEntry{0}});

    play(room, clock, sink, *back, hand_, 1000);
    ASSERT_EQ(room.match().phase, rules::Phase::GameOver);
    EXPECT_TRUE(back->error_codes().empty() ||
                std::all_of(back->error_codes().begin(), back->error_codes().end(),
                            [](const std::string& c) { return c == "illegal_placement"; }));
    const proto::MatchJournal& whole = sink.journals.at(id);
    const proto::ReplayResult replayed = proto::replay(whole);
    EXPECT_TRUE(replayed.ok()) << replayed.mismatches << " mismatches";
    EXPECT_EQ(rules::hash_match_state(replayed.state), rules::hash_match_state(room.match()));
    // Turn numbers go on from the old entries: consecutive, none twice.
    int last_turn = -1;
    for (const auto& entry : whole.entries) {
        if (const auto* stroke = std::get_if<proto::StrokeEntry>(&entry.event)) {
            if (last_turn >= 0) {
                EXPECT_EQ(stroke->turn, last_turn + 1);
            }
            last_turn = stroke->turn;
        }
    }
}

TEST_F(RoomRestore, ASeatNeverResumedIsForfeitedWhenItsGraceEnds) {
    ASSERT_EQ(play(original_, clock_, sink_, *asha_, hand_, 2), 2);
    const proto::MatchJournal before = journal();
    RecordingJournal sink;
    sink.journals[before.created.match_id] = before;
    RoomConfig config = restore_config();
    config.rules.shot_clock_s = 0.0; // no clock in the room's config: the journal's rules count
    Room room("RSTAAA", config, clock_, counters_, nullptr, &sink);
    ASSERT_EQ(room.restore(before, {RestoredSeat{1, nullptr},
                                    RestoredSeat{-1, std::make_shared<SpreadBrain>()}}),
              std::nullopt);
    EXPECT_EQ(room.match().config.shot_clock_s, 20.0);
    // Nobody shoots: the clock may run out on the way; the grace period ends the game.
    for (int i = 0; i < 100 && room.match().phase != rules::Phase::GameOver; ++i) {
        (void)room.take_bot_turn(); // handed out, never played
        const auto wake = room.next_wake_ms();
        ASSERT_TRUE(wake);
        clock_.set_ms(std::max(clock_.now_ms(), *wake));
        room.tick();
    }
    ASSERT_EQ(room.match().phase, rules::Phase::GameOver);
    const auto& entries = sink.journals[before.created.match_id].entries;
    bool forfeited = false;
    for (const auto& entry : entries) {
        if (const auto* f = std::get_if<proto::ForfeitEntry>(&entry.event)) {
            forfeited = f->seat == 0 && f->reason == proto::ForfeitReason::GraceExpired;
        }
    }
    EXPECT_TRUE(forfeited);
    EXPECT_TRUE(proto::replay(sink.journals[before.created.match_id]).ok());
}

TEST_F(RoomRestore, AJournalThatDoesNotReplayIsRefusedAndTheRoomStaysEmpty) {
    ASSERT_EQ(play(original_, clock_, sink_, *asha_, hand_, 3), 3);
    proto::MatchJournal tampered = journal();
    for (auto& entry : tampered.entries) {
        if (auto* stroke = std::get_if<proto::StrokeEntry>(&entry.event)) {
            stroke->shot.power *= 0.5;
            break;
        }
    }
    Room room("RSTAAA", restore_config(), clock_, counters_);
    const auto refused = room.restore(
        tampered, {RestoredSeat{1, nullptr}, RestoredSeat{-1, std::make_shared<SpreadBrain>()}});
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->find("does not replay clean"), std::string::npos) << *refused;
    EXPECT_EQ(room.phase(), proto::Phase::Waiting);
    EXPECT_TRUE(room.match_id().empty());
    EXPECT_FALSE(room.room_state(-1).seats[0].occupied);
}

TEST_F(RoomRestore, OtherVersionsOverGamesAndMismatchedSeatsAreRefused) {
    ASSERT_EQ(play(original_, clock_, sink_, *asha_, hand_, 2), 2);
    const auto seats = [] {
        return std::vector<RestoredSeat>{RestoredSeat{1, nullptr},
                                         RestoredSeat{-1, std::make_shared<SpreadBrain>()}};
    };
    proto::MatchJournal other = journal();
    other.created.versions.physics += 1;
    Room a("RSTAAA", restore_config(), clock_, counters_);
    const auto version = a.restore(other, seats());
    ASSERT_TRUE(version);
    EXPECT_NE(version->find("physics"), std::string::npos) << *version;

    Room b("RSTAAA", restore_config(), clock_, counters_);
    const auto no_bot = b.restore(journal(), {RestoredSeat{1, nullptr}, RestoredSeat{2, nullptr}});
    ASSERT_TRUE(no_bot);
    EXPECT_NE(no_bot->find("bot"), std::string::npos) << *no_bot;

    play(original_, clock_, sink_, *asha_, hand_, 1000);
    ASSERT_EQ(original_.match().phase, rules::Phase::GameOver);
    Room c("RSTAAA", restore_config(), clock_, counters_);
    EXPECT_EQ(c.restore(journal(), seats()), std::optional<std::string>("The match is over."));
    EXPECT_EQ(counters_.matches.load(), 0);
}

} // namespace
} // namespace carrom::room
