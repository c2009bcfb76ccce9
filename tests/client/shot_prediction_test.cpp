// Shot prediction on the real MatchModel: the shooter's stroke drawn at once with the exact
// engine, then the server's snapshots (made by room::ShotStream from rules::play_shot, exactly as
// the server makes them) taking over.

#include "carrom/client/match_model.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/proto/codec.hpp"
#include "carrom/room/shot_stream.hpp"
#include "carrom/rules/match.hpp"
#include "common/rules_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <set>
#include <utility>

namespace carrom::client {
namespace {

constexpr double kFrame = 1.0 / 60.0;
constexpr double kShootAt = 1.0;
constexpr double kOneWay = 0.05; // 100 ms round trip

struct Delivery {
    double local_s;
    proto::ServerMessage message;
};

struct Server {
    rules::MatchState match;
    std::vector<Body> server_bodies; // the server's own (unquantised) board before the stroke
    rules::PlayResult result;
    Trajectory trajectory; // the server's exact trajectory of the stroke
    double end_s = 0.0;
};

proto::Baseline baseline_of(rules::Side side) {
    return side; // the wire's baseline is the rules' side
}

proto::RoomState room_state(const rules::MatchState& m) {
    proto::RoomState r;
    r.code = "PRD234";
    r.you = m.turn_seat;
    r.rule_set = proto::RuleSet::Icf;
    r.seats.resize(m.seats.size());
    for (std::size_t i = 0; i < m.seats.size(); ++i) {
        r.seats[i] = {true,  "P" + std::to_string(i), true,
                      false, proto::Colour::None,     baseline_of(m.seats[i].side)};
    }
    r.scores.assign(m.seats.size(), 0);
    r.dues.assign(m.seats.size(), 0);
    r.turn = m.turn_number;
    r.to_play = m.turn_seat;
    r.phase = proto::Phase::Aiming;
    r.server_time_ms = 1'000'000;
    for (const Body& b : m.bodies) { // exact, as the room sends it (proto::to_board_body)
        r.bodies.push_back({b.id, b.kind, b.pos_px, {}, b.pocketed});
    }
    return r;
}

const Shot kBreak{300.0, -std::numbers::pi / 2.0, 20.0};

// The server's board: the standard layout, or (`on_grid`) the same layout rounded to 0.01 px.
// Either way room_state carries it exactly, so the prediction starts from the server's input.
Server play(const Shot& shot, bool on_grid) {
    Server s;
    s.match = rules::new_match(rules::RuleSet::Icf, rules::RulesConfig{}, PhysicsConfig{});
    if (on_grid) {
        for (Body& b : s.match.bodies) {
            b.pos_px = {proto::quantise(b.pos_px.x), proto::quantise(b.pos_px.y)};
        }
    }
    ExactEngine engine(s.match.physics);
    rules::PlayOptions options;
    options.record_trajectory = true;
    s.result = rules::play_shot(s.match, s.match.turn_seat, shot, engine, options);
    EXPECT_FALSE(s.result.error.has_value());
    s.trajectory = s.result.outcome.physics.trajectory;
    s.end_s = s.result.outcome.physics.end_time_s;
    return s;
}

// The server's messages of the stroke as the room sends them (snapshots at 60 Hz from when the
// shot arrives, physics events before each, the final keyframe of the board with the striker on
// the next shooter's baseline), each arriving kOneWay after it is sent. `nudge` moves one body in
// every message that carries it (a server whose physics differs). `at_motion_changes`: a
// snapshot at every change of motion as well (a contact, a stop, a pocketing), at its exact time,
// as the room sends them; the shot is made at local shoot_at.
std::vector<Delivery> stream(const Server& s, std::optional<int> nudge_id, Vec2 nudge,
                             bool at_motion_changes = false, double shoot_at = kShootAt) {
    const SimResult& physics = s.result.outcome.physics;
    room::ShotStream stream(s.match.physics, physics.trajectory, physics.events, physics.end_time_s,
                            s.match.turn_number);
    auto nudged = [&](proto::Snapshot snap) {
        for (proto::SnapshotBody& b : snap.bodies) {
            if (nudge_id && b.id == *nudge_id) {
                b.pos_px += nudge;
            }
        }
        return snap;
    };
    std::vector<Delivery> out;
    const double sent0 = shoot_at + kOneWay; // the server plays the shot when it arrives
    std::int64_t seq = 100;
    // The step at shot time t: its events, then its snapshot, arriving a one-way trip later.
    auto send = [&](double t) {
        room::ShotStream::Step step = stream.advance(t, ++seq);
        const double arrive = sent0 + std::min(t, s.end_s) + kOneWay;
        for (proto::Event& e : step.events) {
            out.push_back({arrive, proto::ServerMessage{std::move(e)}});
        }
        out.push_back({arrive, proto::ServerMessage{nudged(step.snapshot)}});
        return std::pair{step.finished, arrive};
    };
    for (int k = 0;; ++k) {
        while (at_motion_changes) {
            const std::optional<double> change = stream.next_motion_change(k * kFrame);
            if (!change || *change >= k * kFrame) {
                break;
            }
            send(*change);
        }
        const auto [finished, arrive] = send(k * kFrame);
        if (finished) {
            std::vector<Body> board = s.result.state.bodies;
            board.push_back(rules::striker_for(
                s.match.physics,
                s.result.state.seats[static_cast<std::size_t>(s.result.state.turn_seat)].side,
                Shot{300.0, 0.0, 0.0}));
            out.push_back({arrive, proto::ServerMessage{nudged(room::make_keyframe(
                                       board, ++seq, s.match.turn_number, s.end_s))}});
            break;
        }
    }
    return out;
}

struct Client {
    MatchModel model{PhysicsConfig{}};
    std::vector<Delivery> inbox;
    std::size_t next = 0;
    double local_s = 0.0;

    // One frame: deliver what has arrived, then render.
    std::vector<RenderedBody> frame(double at_s) {
        local_s = at_s;
        while (next < inbox.size() && inbox[next].local_s <= at_s) {
            model.handle(inbox[next].message, inbox[next].local_s);
            ++next;
        }
        return model.render(at_s);
    }
};

void start(Client& c, const Server& s) {
    c.model.handle(room_state(s.match), 0.0);
    for (double t = 0.0; t < kShootAt; t += kFrame) {
        c.frame(t);
    }
}

proto::Shoot shoot_of(const Server& s, const Shot& shot) {
    return proto::Shoot{s.match.turn_number, shot.x_px, shot.angle_rad, shot.power};
}

const RenderedBody* find(const std::vector<RenderedBody>& bodies, int id) {
    const auto it = std::find_if(bodies.begin(), bodies.end(),
                                 [id](const RenderedBody& b) { return b.id == id; });
    return it != bodies.end() ? &*it : nullptr;
}

// The worst distance, over the frames from local from_s until the stroke ends, between each
// drawn body and the server's exact state at the same shot time (plus the nudge for one body).
double worst_after(Client& c, const Server& s, double from_s, std::optional<int> nudge_id,
                   Vec2 nudge, double& rms_px) {
    double worst = 0.0;
    double sum2 = 0.0;
    long samples = 0;
    const double offset = c.model.prediction().offset_s();
    for (double t = kShootAt + kFrame; t < kShootAt + s.end_s + 1.0; t += kFrame) {
        const std::vector<RenderedBody> drawn = c.frame(t);
        const double shot_t = c.model.rendered_time_s() - offset;
        if (t < from_s || shot_t > s.end_s) {
            continue;
        }
        for (const Body& b : state_at(s.match.physics, s.trajectory, shot_t)) {
            const RenderedBody* d = find(drawn, b.id);
            if (b.pocketed || d == nullptr || d->falling) {
                continue;
            }
            const Vec2 truth = b.pos_px + (nudge_id && b.id == *nudge_id ? nudge : Vec2{});
            const double error = length(d->pos_px - truth);
            worst = std::max(worst, error);
            sum2 += error * error;
            ++samples;
        }
    }
    rms_px = samples > 0 ? std::sqrt(sum2 / static_cast<double>(samples)) : 0.0;
    return worst;
}

void expect_final_is_keyframe(Client& c, const std::vector<Delivery>& inbox) {
    const auto last = std::find_if(inbox.rbegin(), inbox.rend(), [](const Delivery& d) {
        const auto* snap = std::get_if<proto::Snapshot>(&d.message);
        return snap != nullptr && snap->keyframe;
    });
    ASSERT_NE(last, inbox.rend());
    const auto& key = std::get<proto::Snapshot>(last->message);
    EXPECT_FALSE(c.model.prediction().active());
    const std::vector<RenderedBody> drawn = c.frame(c.local_s + kFrame);
    for (const proto::SnapshotBody& b : key.bodies) {
        const RenderedBody* d = find(drawn, b.id);
        ASSERT_NE(d, nullptr) << "body " << b.id;
        EXPECT_EQ(d->pos_px, b.pos_px) << "body " << b.id; // exactly
    }
    for (int id : key.pocketed) {
        EXPECT_EQ(find(drawn, id), nullptr) << "body " << id;
    }
}

TEST(ShotPrediction, TheFirstFrameAfterTheShotShowsTheStrikerMoving) {
    const Server s = play(kBreak, true);
    Client c;
    start(c, s);
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    const std::vector<RenderedBody> drawn = c.frame(kShootAt + kFrame);
    const RenderedBody* striker = find(drawn, kStrikerId);
    ASSERT_NE(striker, nullptr);
    const double baseline = baseline_y(s.match.physics, Baseline::Bottom);
    EXPECT_LT(striker->pos_px.y, baseline - 1.0); // moving up the board already
    EXPECT_TRUE(c.model.animating());
}

TEST(ShotPrediction, TheServersSnapshotsOfTheSameStrokeConfirmItWithoutCorrections) {
    const Server s = play(kBreak, true);
    Client c;
    start(c, s);
    c.inbox = stream(s, std::nullopt, {});
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    const double blend_done = kShootAt + 2.0 * kOneWay + 0.1;
    double rms = 0.0;
    EXPECT_LT(worst_after(c, s, blend_done, std::nullopt, {}, rms), 0.01);
    EXPECT_EQ(c.model.prediction_stats().corrections, 0);
    EXPECT_LT(c.model.prediction_stats().max_difference_px, 0.5);
    EXPECT_EQ(c.model.prediction_stats().strokes, 1);
    expect_final_is_keyframe(c, c.inbox);
}

TEST(ShotPrediction, AServerThatDiffersByFivePixelsIsReachedWithin100Ms) {
    const Server s = play(kBreak, true);
    Client c;
    start(c, s);
    const Vec2 nudge{5.0, 0.0};
    c.inbox = stream(s, kStrikerId, nudge);
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    // The first snapshot (it carries the striker) arrives a round trip after the shot.
    const double blend_done = kShootAt + 2.0 * kOneWay + 0.1 + kFrame;
    double rms = 0.0;
    EXPECT_LT(worst_after(c, s, blend_done, kStrikerId, nudge, rms), 0.01);
    EXPECT_GE(c.model.prediction_stats().corrections, 1);
    EXPECT_NEAR(c.model.prediction_stats().max_difference_px, 5.0, 0.05);
    expect_final_is_keyframe(c, c.inbox);
    const auto& lines = c.model.log().all();
    EXPECT_TRUE(std::any_of(lines.begin(), lines.end(), [](const HudLine& l) {
        return l.text == "The server corrected the predicted shot: 1 piece moved, by up to 5.00 px";
    }));
}

// The real case: the standard layout, exact on the server and (through room_state) on the client.
// A break amplifies any start difference to pixels, so this fails if the client's board at rest
// is not the server's exactly.
TEST(ShotPrediction, AnExactServerBoardIsFollowedAndEndsOnItsKeyframe) {
    const Server s = play(kBreak, false);
    Client c;
    start(c, s);
    c.inbox = stream(s, std::nullopt, {});
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    const double blend_done = kShootAt + 2.0 * kOneWay + 0.1;
    double rms = 0.0;
    const double worst = worst_after(c, s, blend_done, std::nullopt, {}, rms);
    const PredictionStats& stats = c.model.prediction_stats();
    // The same build simulates the same stroke from the same exact board: only the snapshots'
    // rounding (at most 0.005 px per coordinate) separates them, below the blend threshold.
    EXPECT_EQ(stats.corrections, 0);
    EXPECT_LE(stats.max_difference_px, 0.0071);
    EXPECT_LT(rms, 0.01);
    EXPECT_LT(worst, 0.01);
    expect_final_is_keyframe(c, c.inbox);
}

TEST(ShotPrediction, ARefusedShotGoesBackToTheBoardAtRest) {
    const Server s = play(kBreak, true);
    Client c;
    start(c, s);
    const std::vector<BodyState> rest = c.model.board_now();
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    c.frame(kShootAt + kFrame);
    c.inbox.push_back({kShootAt + 2.0 * kOneWay,
                       proto::ServerMessage{proto::Error{std::string(proto::code::kInMotion),
                                                         "Wait until the pieces stop."}}});
    const std::vector<RenderedBody> drawn = c.frame(kShootAt + 2.0 * kOneWay);
    EXPECT_FALSE(c.model.prediction().active());
    EXPECT_EQ(c.model.view().phase, proto::Phase::Aiming);
    EXPECT_FALSE(c.model.animating());
    EXPECT_EQ(find(drawn, kStrikerId), nullptr); // drawn where the shooter places it
    for (const BodyState& b : rest) {
        if (b.id == kStrikerId || b.pocketed) {
            continue;
        }
        const RenderedBody* d = find(drawn, b.id);
        ASSERT_NE(d, nullptr);
        EXPECT_EQ(d->pos_px, b.pos_px) << "body " << b.id;
    }
    c.model.take_sounds();
    for (double t = kShootAt + 2.0 * kOneWay; t < kShootAt + 3.0; t += kFrame) {
        c.frame(t);
    }
    EXPECT_TRUE(c.model.take_sounds().empty()); // the predicted collisions are not heard
    EXPECT_FALSE(c.model.animating());
}

TEST(ShotPrediction, NotOnTheOpponentsTurn) {
    const Server s = play(kBreak, true);
    Client c;
    proto::RoomState r = room_state(s.match);
    r.you = 1 - r.to_play;
    c.model.handle(r, 0.0);
    c.frame(0.5);
    EXPECT_FALSE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    EXPECT_FALSE(c.model.prediction().active());
}

TEST(ShotPrediction, PredictedSoundsPlayOnceWhenTheServersEventsArrive) {
    const Server s = play(kBreak, true);
    Client c;
    start(c, s);
    c.inbox = stream(s, std::nullopt, {});
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    const std::vector<SoundCue> predicted = c.model.prediction().cues();
    // A sound by its kind and its time in whole ms: cues of one kind in the same ms are one sound.
    using Sound = std::pair<SoundKind, double>;
    auto sound = [](const SoundCue& cue) {
        return Sound{cue.kind, std::floor(cue.time_s * 1000.0 + 0.5)};
    };
    std::set<Sound> heard;
    for (double t = kShootAt + kFrame; t < kShootAt + s.end_s + 1.0; t += kFrame) {
        c.frame(t);
        for (const SoundCue& cue : c.model.take_sounds()) {
            EXPECT_TRUE(heard.insert(sound(cue)).second) << "heard twice at " << cue.time_s;
        }
    }
    std::set<Sound> expected_sounds;
    for (const SoundCue& cue : predicted) {
        expected_sounds.insert(sound(cue));
    }
    EXPECT_EQ(heard, expected_sounds);
    EXPECT_LT(expected_sounds.size(), predicted.size()); // the break's mirrored coins: merged
    std::size_t expected = 0;
    for (const Event& e : s.result.outcome.physics.events) {
        if (e.kind == EventKind::Pocket ||
            ((e.kind == EventKind::Collision || e.kind == EventKind::Cushion) &&
             loudness_from_impulse(e.impulse) > 0.0)) {
            ++expected;
        }
    }
    EXPECT_GT(expected, 0u);
    EXPECT_EQ(predicted.size(), expected);
}

// The link breaks while the predicted stroke moves: its last deltas and keyframe are lost, and
// the resume brings the room state of the next turn (a new welcome, then room_state). The
// prediction ends with it, so the board is no longer taken for moving and the player can aim.
TEST(ShotPrediction, AResumeAfterTheStrokeEndedEndsThePrediction) {
    const Server s = play(kBreak, true);
    Client c;
    start(c, s);
    ASSERT_TRUE(c.model.predict(shoot_of(s, kBreak), kShootAt));
    std::vector<Delivery> inbox = stream(s, std::nullopt, {});
    inbox.resize(inbox.size() / 3); // the rest went down with the connection
    c.inbox = inbox;
    const double resumed_at = kShootAt + s.end_s + 3.0;
    proto::RoomState after = room_state(s.result.state);
    after.you = s.match.turn_seat;
    c.inbox.push_back({resumed_at, proto::ServerMessage{proto::Welcome{}}});
    c.inbox.push_back({resumed_at, proto::ServerMessage{after}});
    for (double t = kShootAt + kFrame; t < resumed_at; t += kFrame) {
        c.frame(t);
    }
    ASSERT_TRUE(c.model.prediction().active()); // still waiting for the stroke's end
    for (double t = resumed_at; t < resumed_at + 0.5; t += kFrame) {
        c.frame(t);
    }
    EXPECT_FALSE(c.model.prediction().active());
    EXPECT_FALSE(c.model.animating());
}

} // namespace
} // namespace carrom::client

namespace carrom::client {
namespace {

// Doubles: the shooter's stroke from each of the four baselines (a break towards the centre),
// the server's stream of the same stroke confirms the prediction without a correction.
Server play_doubles_from(int seat, const Shot& shot) {
    Server s;
    rules::RulesConfig config;
    config.seat_count = 4;
    s.match = rules::new_match(rules::RuleSet::Icf, config, PhysicsConfig{});
    for (Body& b : s.match.bodies) {
        b.pos_px = {proto::quantise(b.pos_px.x), proto::quantise(b.pos_px.y)};
    }
    s.match.turn_seat = seat;
    ExactEngine engine(s.match.physics);
    rules::PlayOptions options;
    options.record_trajectory = true;
    s.result = rules::play_shot(s.match, seat, shot, engine, options);
    EXPECT_FALSE(s.result.error.has_value()) << seat;
    s.trajectory = s.result.outcome.physics.trajectory;
    s.end_s = s.result.outcome.physics.end_time_s;
    return s;
}

TEST(ShotPrediction, EverySeatOfDoublesIsConfirmedWithoutCorrections) {
    const double towards_centre[] = {-std::numbers::pi / 2.0, std::numbers::pi,
                                     std::numbers::pi / 2.0, 0.0};
    for (int seat = 0; seat < 4; ++seat) {
        const Shot shot{300.0, towards_centre[seat], 20.0};
        const Server s = play_doubles_from(seat, shot);
        Client c;
        start(c, s);
        c.inbox = stream(s, std::nullopt, {});
        ASSERT_TRUE(c.model.predict(shoot_of(s, shot), kShootAt)) << seat;
        const double blend_done = kShootAt + 2.0 * kOneWay + 0.1;
        double rms = 0.0;
        EXPECT_LT(worst_after(c, s, blend_done, std::nullopt, {}, rms), 0.01) << seat;
        EXPECT_EQ(c.model.prediction_stats().corrections, 0) << seat;
        EXPECT_LT(c.model.prediction_stats().max_difference_px, 0.5) << seat;
    }
}

// The room also sends a snapshot at the exact time of every change of motion, pocketings
// included. Compared on the continuous timeline (offset + t - offset), such a time can land a
// hair before the pocketing, where the prediction still has the piece on the board: the client
// compares at the snapshot's own t. Shot at many local times, so that many offsets are tried.
TEST(ShotPrediction, SnapshotsAtTheInstantOfAPocketingConfirmItWithoutCorrections) {
    Server s;
    s.match = rules::new_match(rules::RuleSet::Icf, rules::RulesConfig{}, PhysicsConfig{});
    rules::test::put(s.match, rules::test::kWhite, rules::test::kNearPocket);
    const Shot shot = rules::test::towards_pocket(s.match, 0, rules::test::kHard);
    ExactEngine engine(s.match.physics);
    rules::PlayOptions options;
    options.record_trajectory = true;
    s.result = rules::play_shot(s.match, 0, shot, engine, options);
    ASSERT_FALSE(s.result.error.has_value());
    ASSERT_EQ(s.result.outcome.pocketed, std::vector<int>{rules::test::kWhite});
    ASSERT_TRUE(s.result.outcome.striker_pocketed); // a foul: the turn passes
    s.trajectory = s.result.outcome.physics.trajectory;
    s.end_s = s.result.outcome.physics.end_time_s;
    for (int j = 0; j < 40; ++j) {
        SCOPED_TRACE("shot at local " + std::to_string(j));
        const double shoot_at = kShootAt + 0.0173 * j;
        Client c;
        c.model.handle(room_state(s.match), 0.0);
        for (double t = 0.0; t < shoot_at; t += kFrame) {
            c.frame(t);
        }
        c.inbox = stream(s, std::nullopt, {}, true, shoot_at);
        ASSERT_TRUE(c.model.predict(shoot_of(s, shot), shoot_at));
        for (double t = shoot_at; t < shoot_at + s.end_s + 1.0; t += kFrame) {
            c.frame(t);
        }
        EXPECT_EQ(c.model.prediction_stats().corrections, 0);
        EXPECT_LT(c.model.prediction_stats().max_difference_px, 0.01);
        EXPECT_FALSE(c.model.prediction().active());
    }
}

} // namespace
} // namespace carrom::client
