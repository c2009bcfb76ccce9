// ReplayModel: seeded games journaled as the server journals them (tests/proto/journal_support.hpp)
// and played back: every input ends in the state replay() reaches, a stroke shows at shot time t
// what the server's ShotStream sent at t, and the playback controls do what the keys promise.

#include "carrom/client/replay_model.hpp"
#include "carrom/client/stream_quantise.hpp"

#include "proto/journal_support.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"
#include "carrom/result_hash.hpp"
#include "carrom/room/shot_stream.hpp"
#include "carrom/rules/state_hash.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <tuple>

namespace carrom::client {
namespace {

ReplayModel load_ok(const proto::MatchJournal& journal) {
    auto loaded = ReplayModel::load(journal);
    if (auto* error = std::get_if<proto::Error>(&loaded)) {
        ADD_FAILURE() << error->code << " " << error->path << ": " << error->message;
        std::abort();
    }
    return std::get<ReplayModel>(std::move(loaded));
}

const proto::MatchJournal& game_journal() {
    static const proto::MatchJournal journal =
        proto::test::random_game(rules::RuleSet::Icf, 11).journal();
    return journal;
}

// The pieces (not the striker) by id: pocketed ones without a position.
struct Piece {
    bool pocketed = false;
    Vec2 pos;
    friend bool operator==(const Piece&, const Piece&) = default;
};
std::map<int, Piece> pieces(const std::vector<Body>& bodies) {
    std::map<int, Piece> out;
    for (const Body& raw : bodies) {
        const Body b = stream_quantised(raw);
        if (b.id != kStrikerId) {
            out[b.id] = b.pocketed ? Piece{true, {}} : Piece{false, b.pos_px};
        }
    }
    return out;
}

// Every body as (id, position, velocity, pocketed), in order.
std::vector<std::tuple<int, Vec2, Vec2, bool>> all_of(const std::vector<Body>& bodies) {
    std::vector<std::tuple<int, Vec2, Vec2, bool>> out;
    for (const Body& b : bodies) {
        out.emplace_back(b.id, b.pos_px, b.vel_px_s, b.pocketed);
    }
    return out;
}

TEST(ReplayModel, EveryInputEndsInTheStateReplayReaches) {
    const proto::MatchJournal& journal = game_journal();
    const ReplayModel model = load_ok(journal);
    proto::ReplayOptions options;
    options.keep_physics = true;
    const proto::ReplayResult replayed = proto::replay(journal, options);
    ASSERT_TRUE(replayed.ok());
    ASSERT_EQ(model.turns().size(), replayed.steps.size());
    EXPECT_EQ(model.mismatches(), 0);
    int strokes = 0;
    for (std::size_t i = 0; i < model.turns().size(); ++i) {
        const ReplayTurn& turn = model.turns()[i];
        const proto::ReplayStep& step = replayed.steps[i];
        EXPECT_EQ(turn.entry, step.entry);
        EXPECT_TRUE(turn.matches_journal);
        EXPECT_EQ(rules::hash_match_state(turn.result), step.replayed.state_hash) << i;
        // After the motion: the board as the rules left it.
        EXPECT_EQ(pieces(model.bodies_at(turn.rest_s)), pieces(turn.result.bodies)) << i;
        EXPECT_EQ(&model.state_at_time(turn.rest_s), &turn.result);
        if (turn.stroke) {
            ++strokes;
            EXPECT_EQ(turn.stroke_number, strokes);
            ResultHash hash;
            hash.add(turn.outcome.physics);
            EXPECT_EQ(hash.value(), step.result_hash) << i;
            // The motion's last instant: the simulation's final bodies.
            EXPECT_EQ(pieces(model.bodies_in_stroke(i, turn.outcome.physics.end_time_s)),
                      pieces(step.outcome.physics.bodies))
                << i;
        }
    }
    EXPECT_EQ(model.stroke_count(), strokes);
    EXPECT_GT(strokes, 10);
    EXPECT_EQ(rules::hash_match_state(model.final_state()),
              rules::hash_match_state(replayed.state));
    EXPECT_EQ(pieces(model.bodies_at(model.duration_s())), pieces(replayed.state.bodies));
}

// The live stream's sampling: the same shot times give the same quantised bodies, bit for bit.
TEST(ReplayModel, AStrokeShowsWhatTheShotStreamSentAtTheSameShotTime) {
    const proto::MatchJournal& journal = game_journal();
    const ReplayModel model = load_ok(journal);
    proto::ReplayOptions options;
    options.record_trajectory = true;
    const proto::ReplayResult replayed = proto::replay(journal, options);
    ASSERT_TRUE(replayed.ok());
    std::size_t compared = 0;
    for (std::size_t i = 0; i < model.turns().size(); ++i) {
        if (!model.turns()[i].stroke) {
            continue;
        }
        const SimResult& physics = replayed.steps[i].outcome.physics;
        room::ShotStream stream(journal.created.physics, physics.trajectory, physics.events,
                                physics.end_time_s, 0);
        for (int k = 0;; ++k) {
            const double t = k / 30.0; // the server's default snapshot rate
            const room::ShotStream::Step step = stream.advance(t, k);
            const proto::Snapshot sent = stream.keyframe(k);
            const std::vector<Body> shown = model.bodies_in_stroke(i, step.snapshot.t_s);
            std::set<int> pocketed;
            std::map<int, std::pair<Vec2, Vec2>> moving;
            for (const Body& b : shown) {
                if (b.pocketed) {
                    pocketed.insert(b.id);
                } else {
                    moving[b.id] = {b.pos_px, b.vel_px_s};
                }
            }
            EXPECT_EQ(pocketed, std::set<int>(sent.pocketed.begin(), sent.pocketed.end()));
            ASSERT_EQ(moving.size(), sent.bodies.size());
            for (const proto::SnapshotBody& b : sent.bodies) {
                ASSERT_TRUE(moving.contains(b.id));
                EXPECT_EQ(moving[b.id].first, b.pos_px) << "stroke " << i << " t " << t;
                EXPECT_EQ(moving[b.id].second, b.vel_px_s) << "stroke " << i << " t " << t;
            }
            ++compared;
            if (step.finished) {
                break;
            }
        }
    }
    EXPECT_GT(compared, 100U);
}

TEST(ReplayModel, ShotTimeOnTheTimelineIsTheStrokesOwn) {
    const ReplayModel model = load_ok(game_journal());
    const auto& turns = model.turns();
    const auto it = std::find_if(turns.begin(), turns.end(), [](const ReplayTurn& t) {
        return t.stroke && t.rest_s - t.motion_s > 0.5;
    });
    ASSERT_NE(it, turns.end());
    const auto i = static_cast<std::size_t>(it - turns.begin());
    const double time = it->motion_s + 0.25;
    ASSERT_TRUE(model.shot_time_at(time));
    EXPECT_EQ(*model.shot_time_at(time), time - it->motion_s);
    EXPECT_EQ(all_of(model.bodies_at(time)),
              all_of(model.bodies_in_stroke(i, time - it->motion_s)));
    EXPECT_EQ(model.room_state_at(time).phase, proto::Phase::Moving);
    EXPECT_FALSE(model.shot_time_at(it->start_s));
    EXPECT_FALSE(model.shot_time_at(it->rest_s));
}

TEST(ReplayModel, NextAndPreviousJumpToAnInputsStartBoard) {
    ReplayModel model = load_ok(game_journal());
    const auto& turns = model.turns();
    ASSERT_GT(turns.size(), 3U);
    model.pause();
    EXPECT_EQ(model.current_turn(), 0U);
    EXPECT_EQ(model.stroke_number(), 0);
    model.next_turn();
    EXPECT_EQ(model.time_s(), turns[1].start_s);
    EXPECT_EQ(model.current_turn(), 1U);
    EXPECT_EQ(&model.state_at_time(model.time_s()), &turns[1].before);
    EXPECT_EQ(pieces(model.bodies()), pieces(turns[1].before.bodies));
    model.next_turn();
    EXPECT_EQ(model.current_turn(), 2U);
    // Inside an input: back to its start; at its start: the input before.
    model.seek(turns[2].rest_s);
    model.previous_turn();
    EXPECT_EQ(model.time_s(), turns[2].start_s);
    model.previous_turn();
    EXPECT_EQ(model.time_s(), turns[1].start_s);
    EXPECT_EQ(pieces(model.bodies()), pieces(turns[1].before.bodies));
    model.restart();
    EXPECT_EQ(model.time_s(), 0.0);
    EXPECT_TRUE(model.playing());
    EXPECT_EQ(pieces(model.bodies()), pieces(proto::initial_state(game_journal().created).bodies));
    // Past the last input: the end.
    model.seek(turns.back().start_s);
    model.next_turn();
    EXPECT_TRUE(model.finished());
}

TEST(ReplayModel, TheTurnCounterCountsEveryInputOnceItsLeadIsOver) {
    ReplayModel model = load_ok(game_journal());
    const auto& turns = model.turns();
    model.pause();
    EXPECT_EQ(model.turn_number(), 0);
    int strokes = 0;
    for (std::size_t i = 0; i < turns.size(); ++i) {
        model.seek(turns[i].start_s);
        EXPECT_EQ(model.turn_number(), static_cast<int>(i)) << i;
        model.seek(turns[i].motion_s);
        EXPECT_EQ(model.turn_number(), static_cast<int>(i) + 1) << i;
        strokes += turns[i].stroke ? 1 : 0;
    }
    model.seek(model.duration_s());
    EXPECT_EQ(model.turn_number(), static_cast<int>(turns.size()));
    // Clock expiries and forfeits are turns too: the strokes alone count fewer.
    EXPECT_EQ(model.stroke_count(), strokes);
    ASSERT_LT(static_cast<std::size_t>(strokes), turns.size()) << "the game has clock expiries";
    EXPECT_GT(model.turn_number(), model.stroke_count());
}

TEST(ReplayModel, SpeedStaysWithinAQuarterAndFourTimes) {
    ReplayModel model = load_ok(game_journal());
    EXPECT_EQ(model.speed(), 1.0);
    model.set_speed(10.0);
    EXPECT_EQ(model.speed(), 4.0);
    model.faster();
    EXPECT_EQ(model.speed(), 4.0);
    model.set_speed(0.01);
    EXPECT_EQ(model.speed(), 0.25);
    model.slower();
    EXPECT_EQ(model.speed(), 0.25);
    model.set_speed(1.0);
    model.slower();
    EXPECT_EQ(model.speed(), 0.5);
    model.faster();
    model.faster();
    EXPECT_EQ(model.speed(), 2.0);
    model.set_speed(1.5);
    model.faster();
    EXPECT_EQ(model.speed(), 2.0);
    model.advance(0.5);
    EXPECT_EQ(model.time_s(), 1.0);
    model.toggle_play();
    model.advance(0.5);
    EXPECT_EQ(model.time_s(), 1.0);
    EXPECT_FALSE(model.playing());
}

TEST(ReplayModel, PlayingToTheEndStopsThereWithTheGameOver) {
    ReplayModel model = load_ok(game_journal());
    model.set_speed(4.0);
    int frames = 0;
    while (!model.finished() && frames < 1000000) {
        model.advance(1.0 / 60.0);
        ++frames;
    }
    EXPECT_TRUE(model.finished());
    EXPECT_FALSE(model.playing());
    EXPECT_EQ(model.stroke_number(), model.stroke_count());
    const proto::RoomState end = model.room_state_at(model.time_s());
    EXPECT_EQ(end.phase, proto::Phase::GameOver);
    EXPECT_EQ(end.code, "ABCDEF");
    EXPECT_EQ(end.you, -1);
    bool game_end = false;
    for (const auto& message : model.outcome_messages(model.turns().size() - 1)) {
        if (const auto* e = std::get_if<proto::Event>(&message)) {
            game_end = game_end || std::holds_alternative<proto::GameEndEvent>(*e);
        }
    }
    EXPECT_TRUE(game_end);
    model.play(); // from the end: again from the start
    EXPECT_EQ(model.time_s(), 0.0);
}

TEST(ReplayModel, AJournalOfAnotherPhysicsVersionIsRefusedWithCheckVersionsSentence) {
    proto::MatchJournal journal = game_journal();
    journal.created.versions.physics += 1;
    const auto loaded = ReplayModel::load(journal);
    ASSERT_TRUE(std::holds_alternative<proto::Error>(loaded));
    const auto& error = std::get<proto::Error>(loaded);
    EXPECT_EQ(error.code, proto::replay_code::kVersionMismatch);
    EXPECT_EQ(error, *proto::check_versions(journal.created));
}

TEST(ReplayModel, TextThatIsNotAJournalIsRefusedWithItsPath) {
    auto loaded = ReplayModel::load_text("{\"format\": 1");
    ASSERT_TRUE(std::holds_alternative<proto::Error>(loaded));
    EXPECT_EQ(std::get<proto::Error>(loaded).code, proto::scene_code::kMalformedJson);
    nlohmann::json j = proto::journal_to_json(game_journal());
    j["entries"][3]["shot"]["x"] = "left";
    loaded = ReplayModel::load_text(j.dump());
    ASSERT_TRUE(std::holds_alternative<proto::Error>(loaded));
    EXPECT_EQ(std::get<proto::Error>(loaded).path.rfind("entries[", 0), 0U)
        << std::get<proto::Error>(loaded).path;
    loaded = ReplayModel::load_text(proto::journal_to_json(game_journal()).dump());
    EXPECT_TRUE(std::holds_alternative<ReplayModel>(loaded));
}

TEST(ReplayModel, AStrokeTheRulesRefuseIsABadJournalNamingItsEntry) {
    proto::MatchJournal journal = game_journal();
    for (auto& entry : journal.entries) {
        if (auto* stroke = std::get_if<proto::StrokeEntry>(&entry.event)) {
            stroke->seat = 1 - stroke->seat; // out of turn
            break;
        }
    }
    const auto loaded = ReplayModel::load(journal);
    ASSERT_TRUE(std::holds_alternative<proto::Error>(loaded));
    EXPECT_EQ(std::get<proto::Error>(loaded).code, proto::replay_code::kBadJournal);
}

} // namespace
} // namespace carrom::client
