// Doubles rooms: four seats filled in index order (players and bots at chosen seats), the turn
// passing anticlockwise, partners sharing a score, a side seat's striker on its own baseline,
// the shot clock, forfeits losing for the team, a resumed side seat, the rematch asked by every
// human, and a doubles match restored from its journal.
#include "room/aim_brain.hpp"
#include "room/fake_peer.hpp"
#include "room/recording_journal.hpp"
#include "room/room_fixture.hpp"

#include "carrom/proto/journal_replay.hpp"
#include "carrom/rules/state_hash.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <numbers>
#include <vector>

namespace carrom::room {
namespace {

using testing::AimBrain;
using testing::FakePeer;
using testing::RecordingJournal;

RoomConfig doubles_config() {
    RoomConfig c;
    c.rule_set = proto::RuleSet::Freestyle; // no break rule: a quiet shot passes the turn
    c.rules.seat_count = 4;
    c.rules.shot_clock_s = 0.0;
    c.rules.freestyle.target = 40;
    c.snapshot_hz = 60.0;
    c.contact_snapshots = false;
    c.grace_s = 60.0;
    return c;
}

class DoublesRoom : public ::testing::Test {
protected:
    DoublesRoom() : room_("DBXAAA", doubles_config(), clock_, counters_, nullptr, &sink_) {}

    void seat_all() {
        for (auto& p : players_) {
            ASSERT_FALSE(room_.join(p, proto::Role::Player));
        }
    }

    void play_out() {
        for (int i = 0; i < 100000 && room_.phase() == proto::Phase::Moving; ++i) {
            sink_.confirm_all(room_);
            const auto wake = room_.next_wake_ms();
            ASSERT_TRUE(wake);
            clock_.set_ms(std::max(clock_.now_ms(), *wake));
            room_.tick();
        }
    }

    // A soft shot along the seat's baseline: it pockets nothing and passes the turn.
    void quiet_shot(int seat) {
        const auto side = room_.match().seats[static_cast<std::size_t>(seat)].side;
        const bool across = side == rules::Side::Bottom || side == rules::Side::Top;
        room_.shoot(*players_[static_cast<std::size_t>(seat)],
                    {room_.match().turn_number, 300.0, across ? 0.0 : std::numbers::pi / 2.0, 2.0});
        ASSERT_EQ(room_.phase(), proto::Phase::Moving);
        play_out();
    }

    // Plays strokes until the game is over (or `strokes` were played): humans through their
    // peers, bots through the seam, every shot from `hand` (retried at another spot when the
    // rules refuse its placement). Returns the strokes played.
    int play(int strokes) {
        int played = 0;
        while (played < strokes && room_.match().phase != rules::Phase::GameOver) {
            const rules::MatchState& state = room_.match();
            const int seat = state.turn_seat;
            const auto turn = room_.take_bot_turn();
            for (int attempt = 0; attempt < 20 && room_.phase() != proto::Phase::Moving;
                 ++attempt) {
                const Shot shot = hand_.choose_shot(state, seat, {});
                if (turn) {
                    (void)room_.bot_shoot(seat, turn->turn, shot);
                } else {
                    room_.shoot(*players_[static_cast<std::size_t>(seat)],
                                {state.turn_number, shot.x_px, shot.angle_rad, shot.power});
                }
            }
            if (room_.phase() != proto::Phase::Moving) {
                ADD_FAILURE() << "no stroke accepted at turn " << state.turn_number;
                return played;
            }
            play_out();
            ++played;
        }
        return played;
    }

    ManualClock clock_;
    RoomCounters counters_;
    RecordingJournal sink_;
    Room room_;
    AimBrain hand_;
    std::vector<std::shared_ptr<FakePeer>> players_{
        std::make_shared<FakePeer>(1, "Asha"), std::make_shared<FakePeer>(2, "Bo"),
        std::make_shared<FakePeer>(3, "Cy"), std::make_shared<FakePeer>(4, "Dee")};
    std::shared_ptr<FakePeer> watcher_ = std::make_shared<FakePeer>(9, "Eve");
};

TEST_F(DoublesRoom, FourPlayersTakeTheSeatsInOrderAndTheGameStartsWithTheFourth) {
    for (std::size_t i = 0; i < 3; ++i) {
        ASSERT_FALSE(room_.join(players_[i], proto::Role::Player));
        EXPECT_EQ(room_.seat_of(*players_[i]), static_cast<int>(i));
        EXPECT_EQ(room_.phase(), proto::Phase::Waiting);
    }
    EXPECT_EQ(players_[0]->last_room_state().seats.size(), 4U);
    ASSERT_FALSE(room_.join(players_[3], proto::Role::Player));
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    const auto state = players_[3]->last_room_state();
    EXPECT_EQ(state.you, 3);
    ASSERT_EQ(state.seats.size(), 4U);
    EXPECT_EQ(state.scores.size(), 4U);
    EXPECT_EQ(state.dues.size(), 4U);
    const proto::Baseline sides[] = {proto::Baseline::Bottom, proto::Baseline::Right,
                                     proto::Baseline::Top, proto::Baseline::Left};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(state.seats[i].baseline, sides[i]) << i;
        EXPECT_EQ(state.seats[i].team, static_cast<int>(i % 2)) << i;
        EXPECT_TRUE(state.seats[i].occupied);
    }
    EXPECT_EQ(state.seats[2].name, "Cy");
    ASSERT_EQ(players_[1]->events<proto::TurnEvent>().size(), 1U);
    EXPECT_EQ(players_[1]->events<proto::TurnEvent>()[0].seat, 0);
    auto late = std::make_shared<FakePeer>(5, "Fay");
    const auto full = room_.join(late, proto::Role::Player);
    ASSERT_TRUE(full);
    EXPECT_EQ(full->code, "room_full");
    EXPECT_EQ(sink_.journals.at(room_.match_id()).created.seats.size(), 4U);
    EXPECT_EQ(sink_.journals.at(room_.match_id()).created.rules.seat_count, 4);
}

TEST_F(DoublesRoom, TheTurnPassesAnticlockwiseAndASideSeatShootsFromItsOwnBaseline) {
    seat_all();
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    std::vector<int> order;
    for (int i = 0; i < 5; ++i) {
        const int seat = room_.match().turn_seat;
        order.push_back(seat);
        // The striker waits on the seat's own baseline (80 px inside its edge), at its middle.
        const auto state = watcher_->last_room_state();
        EXPECT_EQ(state.to_play, seat);
        const proto::BoardBody& striker = state.bodies.back();
        ASSERT_EQ(striker.kind, BodyKind::Striker);
        const Vec2 expected[] = {{300.0, 520.0}, {520.0, 300.0}, {300.0, 80.0}, {80.0, 300.0}};
        EXPECT_EQ(striker.pos_px, expected[seat]) << "seat " << seat;
        quiet_shot(seat);
        const auto results = watcher_->all<proto::ShotResult>();
        ASSERT_FALSE(results.empty());
        EXPECT_EQ(results.back().seat, seat);
        EXPECT_EQ(results.back().next_seat, (seat + 1) % 4);
    }
    EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 0}));
    for (auto& p : players_) {
        EXPECT_TRUE(p->error_codes().empty()) << p->name();
    }
}

TEST_F(DoublesRoom, ASideSeatsStrikerOffItsBaselineRangeIsRefused) {
    seat_all();
    quiet_shot(0);
    ASSERT_EQ(room_.match().turn_seat, 1);
    room_.shoot(*players_[1], {room_.match().turn_number, 100.0, std::numbers::pi, 10.0});
    EXPECT_EQ(players_[1]->last_error(), "illegal_placement");
    room_.shoot(*players_[0], {room_.match().turn_number, 300.0, 0.0, 10.0});
    EXPECT_EQ(players_[0]->last_error(), "not_your_turn");
}

TEST_F(DoublesRoom, PartnersShareTheirTeamsScoreUntilTheGameEndsForATeam) {
    ASSERT_FALSE(room_.join(players_[0], proto::Role::Player));
    for (int seat = 1; seat < 4; ++seat) {
        ASSERT_FALSE(room_.seat_bot("Bot (medium)", std::make_shared<AimBrain>(), seat));
    }
    ASSERT_FALSE(room_.join(watcher_, proto::Role::Spectator));
    ASSERT_EQ(room_.phase(), proto::Phase::Aiming);
    const int played = play(400);
    ASSERT_EQ(room_.match().phase, rules::Phase::GameOver) << played << " strokes";
    bool scored = false;
    int expected_next = 0;
    for (const auto& r : watcher_->all<proto::ShotResult>()) {
        ASSERT_EQ(r.scores.size(), 4U);
        EXPECT_EQ(r.scores[0], r.scores[2]);
        EXPECT_EQ(r.scores[1], r.scores[3]);
        EXPECT_EQ(r.points[0], r.points[2]);
        EXPECT_EQ(r.points[1], r.points[3]);
        EXPECT_EQ(r.dues[0], r.dues[2]);
        scored = scored || r.scores[0] != 0 || r.scores[1] != 0;
        EXPECT_EQ(r.seat, expected_next);
        if (!r.board_over && !r.game_over) {
            EXPECT_EQ(r.next_seat, r.extra_turn ? r.seat : (r.seat + 1) % 4);
        }
        expected_next = r.next_seat;
    }
    EXPECT_TRUE(scored);
    const auto ends = watcher_->events<proto::GameEndEvent>();
    ASSERT_EQ(ends.size(), 1U);
    ASSERT_TRUE(ends[0].winner == 0 || ends[0].winner == 1) << ends[0].winner;
    const auto state = watcher_->last_room_state();
    EXPECT_EQ(state.winner, ends[0].winner);
    EXPECT_EQ(state.scores[0], state.scores[2]);
    EXPECT_EQ(state.scores[1], state.scores[3]);
    EXPECT_GE(state.scores[static_cast<std::size_t>(ends[0].winner)], 40);
    const proto::ReplayResult replayed = proto::replay(sink_.journals.at(room_.match_id()));
    EXPECT_TRUE(replayed.ok()) << replayed.mismatches << " mismatches";
}

TEST_F(DoublesRoom, BotsTakeTheirChosenSeatsAndPlayersTheOthersInOrder) {
    ASSERT_FALSE(room_.join(players_[0], proto::Role::Player));
    ASSERT_FALSE(room_.seat_bot("Bot (easy)", std::make_shared<AimBrain>(), 2));
    const auto taken = room_.seat_bot("Bot (easy)", std::make_shared<AimBrain>(), 2);
    ASSERT_TRUE(taken);
    EXPECT_EQ(taken->code, "room_full");
    const auto no_seat = room_.seat_bot("Bot (easy)", std::make_shared<AimBrain>(), 4);
    ASSERT_TRUE(no_seat);
    EXPECT_EQ(no_seat->code, "bad_field");
    ASSERT_FALSE(room_.join(players_[1], proto::Role::Player));
    EXPECT_EQ(room_.seat_of(*players_[1]), 1);
    EXPECT_EQ(room_.phase(), proto::Phase::Waiting);
    ASSERT_FALSE(room_.join(players_[2], proto::Role::Player));
    EXPECT_EQ(room_.seat_of(*players_[2]), 3);
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    const auto state = players_[2]->last_room_state();
    EXPECT_TRUE(state.seats[2].bot);
    EXPECT_EQ(state.seats[2].team, 0); // the bot is seat 0's partner
    EXPECT_FALSE(state.seats[1].bot);
    EXPECT_FALSE(state.seats[3].bot);
}

TEST_F(DoublesRoom, TheShotClockPassesTheTurnToTheNextSeat) {
    RoomConfig c = doubles_config();
    c.rules.shot_clock_s = 5.0;
    Room room("DBXBBB", c, clock_, counters_);
    for (auto& p : players_) {
        ASSERT_FALSE(room.join(p, proto::Role::Player));
    }
    for (int seat = 1; seat <= 3; ++seat) {
        const auto wake = room.next_wake_ms();
        ASSERT_TRUE(wake);
        clock_.set_ms(*wake);
        room.tick();
        EXPECT_EQ(room.match().turn_seat, seat);
    }
    const auto results = players_[2]->all<proto::ShotResult>();
    ASSERT_EQ(results.size(), 3U);
    EXPECT_EQ(results[1].seat, 1);
    ASSERT_EQ(results[1].fouls.size(), 1U);
    EXPECT_EQ(results[1].fouls[0].rule, "shot_clock_expired");
}

TEST_F(DoublesRoom, ASeatThatLeavesLosesTheGameForItsTeam) {
    seat_all();
    quiet_shot(0);
    room_.leave(*players_[3]); // seat 3, team 1
    const auto ends = players_[0]->events<proto::GameEndEvent>();
    ASSERT_EQ(ends.size(), 1U);
    EXPECT_EQ(ends[0].winner, 0);
    EXPECT_EQ(ends[0].reason, "left");
    EXPECT_EQ(room_.phase(), proto::Phase::GameOver);
    const auto state = players_[1]->last_room_state();
    EXPECT_EQ(state.winner, 0);
    EXPECT_FALSE(state.seats[3].occupied);
    EXPECT_TRUE(state.seats[1].occupied);
}

TEST_F(DoublesRoom, ASideSeatResumesAfterADrop) {
    seat_all();
    quiet_shot(0);
    room_.disconnected(*players_[1]); // the right seat, to play
    const auto dropped = players_[0]->events<proto::PlayerDroppedEvent>();
    ASSERT_EQ(dropped.size(), 1U);
    EXPECT_EQ(dropped[0].seat, 1);
    EXPECT_FALSE(players_[2]->last_room_state().seats[1].connected);
    clock_.advance_ms(30000);
    room_.tick();
    auto back = std::make_shared<FakePeer>(2, "Bo");
    ASSERT_FALSE(room_.resume(back));
    const auto state = back->last_room_state();
    EXPECT_EQ(state.you, 1);
    EXPECT_EQ(state.seats[1].baseline, proto::Baseline::Right);
    EXPECT_EQ(state.to_play, 1);
    EXPECT_TRUE(state.seats[1].connected);
    for (std::size_t i : {0U, 2U, 3U}) {
        ASSERT_EQ(players_[i]->events<proto::PlayerReturnedEvent>().size(), 1U);
        EXPECT_EQ(players_[i]->events<proto::PlayerReturnedEvent>()[0].seat, 1);
    }
    players_[1] = back;
    quiet_shot(1);
    EXPECT_EQ(room_.match().turn_seat, 2);
}

TEST_F(DoublesRoom, ARematchStartsWhenEveryHumanSeatAsks) {
    ASSERT_FALSE(room_.join(players_[0], proto::Role::Player));
    ASSERT_FALSE(room_.join(players_[1], proto::Role::Player));
    ASSERT_FALSE(room_.seat_bot("Bot (medium)", std::make_shared<AimBrain>(), 2));
    ASSERT_FALSE(room_.join(players_[2], proto::Role::Player)); // seat 3
    ASSERT_EQ(room_.seat_of(*players_[2]), 3);
    players_[3] = players_[2]; // the human at seat 3
    players_[2] = nullptr;     // seat 2 is the bot's
    play(400);
    ASSERT_EQ(room_.match().phase, rules::Phase::GameOver);
    room_.rematch(*players_[0]);
    room_.rematch(*players_[1]);
    EXPECT_EQ(room_.phase(), proto::Phase::GameOver); // seat 3 has not asked
    EXPECT_EQ(counters_.matches_started_total.load(), 1);
    room_.rematch(*players_[3]);
    EXPECT_EQ(room_.phase(), proto::Phase::Aiming);
    EXPECT_EQ(counters_.matches_started_total.load(), 2);
    EXPECT_EQ(room_.match().turn_seat, 1); // the next seat breaks the next game
    EXPECT_EQ(sink_.order.size(), 2U);
}

TEST_F(DoublesRoom, ADoublesMatchIsRestoredFromItsJournal) {
    ASSERT_FALSE(room_.join(players_[0], proto::Role::Player));
    ASSERT_FALSE(room_.join(players_[1], proto::Role::Player));
    ASSERT_FALSE(room_.seat_bot("Bot (medium)", std::make_shared<AimBrain>(), 2));
    ASSERT_FALSE(room_.seat_bot("Bot (medium)", std::make_shared<AimBrain>(), 3));
    ASSERT_EQ(play(2), 2);
    ASSERT_NE(room_.match().phase, rules::Phase::GameOver);
    const proto::MatchJournal before = sink_.journals.at(room_.match_id());

    ManualClock clock(clock_.now_ms() + 5000);
    RoomCounters counters;
    RecordingJournal sink;
    sink.journals[before.created.match_id] = before;
    Room room("DBXAAA", doubles_config(), clock, counters, nullptr, &sink);
    ASSERT_EQ(room.restore(before, {RestoredSeat{11, nullptr}, RestoredSeat{12, nullptr},
                                    RestoredSeat{-1, std::make_shared<AimBrain>()},
                                    RestoredSeat{-1, std::make_shared<AimBrain>()}}),
              std::nullopt);
    EXPECT_EQ(rules::hash_match_state(room.match()), rules::hash_match_state(room_.match()));
    const proto::RoomState state = room.room_state(-1);
    ASSERT_EQ(state.seats.size(), 4U);
    EXPECT_FALSE(state.seats[1].connected);
    EXPECT_EQ(state.seats[1].name, "Bo");
    EXPECT_EQ(state.seats[1].baseline, proto::Baseline::Right);
    EXPECT_TRUE(state.seats[3].bot);
    auto back = std::make_shared<FakePeer>(12, "Bo");
    ASSERT_FALSE(room.resume(back));
    EXPECT_EQ(back->last_room_state().you, 1);
    EXPECT_EQ(back->last_room_state().seats[1].team, 1);

    // A room of the other size refuses the journal.
    RoomConfig singles = doubles_config();
    singles.rules.seat_count = 2;
    Room two("DBXCCC", singles, clock, counters);
    const auto refused =
        two.restore(before, {RestoredSeat{11, nullptr}, RestoredSeat{12, nullptr}});
    ASSERT_TRUE(refused);
}

} // namespace
} // namespace carrom::room
