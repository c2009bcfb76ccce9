// `carrom-sim --frame-error FRAMES JOURNAL`: the built binary measures frame logs written from a
// journal's exact trajectories (no error, every final board equal), finds a displaced body (its
// error, a jump), a held picture (a freeze) and a final board off by 0.01 px, and refuses a bad
// frame log or journal with a code and a sentence (exit 2).

#include "proto/journal_support.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"
#include "tools/sim_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;
using sim_testing::run_sim;
using sim_testing::SimRun;
using sim_testing::temp_path;

constexpr double kFrameS = 1.0 / 60.0;

// One frame line as carrom-client --frame-log writes it.
struct FrameLine {
    int turn = -1;
    double t_s = 0.0;
    std::vector<Body> bodies; // pocketed ones are left out of the line
};

// Frames of every stroke of the journal drawn exactly: t = 0, 1/60, ... up to the stroke's end,
// then three frames at rest with the server's final board (returned pieces placed).
std::vector<FrameLine> exact_frames(const MatchJournal& journal) {
    ReplayOptions options;
    options.record_trajectory = true;
    const ReplayResult r = replay(journal, options);
    std::vector<FrameLine> frames;
    for (const ReplayStep& step : r.steps) {
        const rules::ShotOutcome& o = step.outcome;
        if (!o.shot_taken) {
            continue;
        }
        for (double t = 0.0; t < o.physics.end_time_s; t += kFrameS) {
            frames.push_back(
                {o.turn_number, t, state_at(journal.created.physics, o.physics.trajectory, t)});
        }
        std::vector<Body> rest = o.physics.bodies;
        for (Body& b : rest) {
            for (const rules::ReturnedPiece& p : o.returned) {
                if (p.id == b.id) {
                    b.pos_px = p.pos_px;
                    b.pocketed = false;
                }
            }
        }
        for (int i = 0; i < 3; ++i) {
            frames.push_back({o.turn_number, o.physics.end_time_s + i * kFrameS, rest});
        }
    }
    return frames;
}

std::string write_log(const std::vector<FrameLine>& frames) {
    const std::string path = temp_path("frames.jsonl");
    std::ofstream out(path);
    out << Json{{"ms", 0.0}, {"kind", "shoot"}, {"turn", 0}, {"x", 1.0}}.dump() << '\n';
    long index = 0;
    for (const FrameLine& f : frames) {
        Json bodies = Json::array();
        for (const Body& b : f.bodies) {
            if (!b.pocketed) {
                bodies.push_back({b.id, b.pos_px.x, b.pos_px.y});
            }
        }
        out << Json{{"ms", 1000.0 * kFrameS * static_cast<double>(index)},
                    {"kind", "frame"},
                    {"frame", index},
                    {"turn", f.turn},
                    {"t", f.t_s},
                    {"bodies", bodies}}
                   .dump()
            << '\n';
        ++index;
    }
    return path;
}

class CarromSimFrameError : public ::testing::Test {
protected:
    void SetUp() override {
        game_ = test::random_game(rules::RuleSet::Freestyle, 5, 6).journal();
        journal_path_ = temp_path("journal.json");
        std::ofstream(journal_path_) << journal_to_json(game_).dump();
        frames_ = exact_frames(game_);
        ASSERT_FALSE(frames_.empty());
    }
    Json measure(const std::vector<FrameLine>& frames) {
        const SimRun run = run_sim("--frame-error " + write_log(frames) + " " + journal_path_);
        EXPECT_EQ(run.exit_code, 0) << run.err;
        return Json::parse(run.out, nullptr, false);
    }
    // The index of a frame in the middle of the first stroke.
    std::size_t middle_of_first_stroke() const {
        std::size_t n = 0;
        while (n < frames_.size() && frames_[n].turn == frames_[0].turn) {
            ++n;
        }
        return (n - 3) / 2;
    }

    MatchJournal game_;
    std::string journal_path_;
    std::vector<FrameLine> frames_;
};

TEST_F(CarromSimFrameError, ExactFramesHaveNoErrorAndTheServersFinalBoards) {
    const Json out = measure(frames_);
    ASSERT_TRUE(out.is_object());
    EXPECT_GT(out["samples"].get<long>(), 100);
    EXPECT_LT(out["max_px"].get<double>(), 1e-9);
    EXPECT_EQ(out["jumps"], 0);
    EXPECT_EQ(out["freezes"], 0);
    EXPECT_NEAR(out["frame_interval_ms"].get<double>(), 1000.0 * kFrameS, 1e-6);
    EXPECT_GT(out["finals_checked"].get<int>(), 0);
    EXPECT_EQ(out["finals_equal"], out["finals_checked"]);
    EXPECT_EQ(out["strokes"].size(), out["finals_checked"].get<std::size_t>());
}

TEST_F(CarromSimFrameError, ADisplacedBodyIsItsErrorAndAJump) {
    std::vector<FrameLine> frames = frames_;
    Body& b = frames[middle_of_first_stroke()].bodies.front();
    ASSERT_FALSE(b.pocketed);
    b.pos_px.x += 100.0;
    const Json out = measure(frames);
    EXPECT_NEAR(out["max_px"].get<double>(), 100.0, 1e-9);
    EXPECT_NEAR(out["strokes"][0]["max_px"].get<double>(), 100.0, 1e-9);
    EXPECT_GT(out["rms_px"].get<double>(), 0.0);
    EXPECT_GE(out["jumps"].get<int>(), 1);
    EXPECT_EQ(out["strokes"][1]["jumps"], 0);
}

TEST_F(CarromSimFrameError, AHeldPictureWhileTheStrokeMovesIsAFreeze) {
    std::vector<FrameLine> frames = frames_;
    const std::size_t at = middle_of_first_stroke();
    for (std::size_t i = at + 1; i <= at + 5; ++i) {
        frames[i].bodies = frames[at].bodies; // drawn unchanged for 5 frames: 6 intervals
    }
    const Json out = measure(frames);
    EXPECT_EQ(out["freezes"], 1);
    EXPECT_NEAR(out["longest_freeze_ms"].get<double>(), 6000.0 * kFrameS, 1e-6);
}

TEST_F(CarromSimFrameError, AFinalBoardOffByAHundredthIsAMismatch) {
    std::vector<FrameLine> frames = frames_;
    std::size_t last = 0;
    while (last + 1 < frames.size() && frames[last + 1].turn == frames[0].turn) {
        ++last;
    }
    for (Body& b : frames[last].bodies) {
        if (!b.pocketed && b.id != kStrikerId) {
            b.pos_px.y += 0.01;
            break;
        }
    }
    const Json out = measure(frames);
    const Json& final = out["strokes"][0]["final"];
    EXPECT_FALSE(final["equal"].get<bool>());
    EXPECT_NEAR(final["max_difference_px"].get<double>(), 0.01, 1e-6);
    EXPECT_EQ(out["finals_equal"].get<int>() + 1, out["finals_checked"].get<int>());
}

TEST_F(CarromSimFrameError, ABadFrameLogOrJournalIsRefused) {
    const std::string bad = temp_path("bad.jsonl");
    std::ofstream(bad) << "{\"kind\": \"frame\", \"ms\": 1}\n";
    SimRun run = run_sim("--frame-error " + bad + " " + journal_path_);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_TRUE(run.out.empty());
    EXPECT_EQ(Json::parse(run.err, nullptr, false)["error"]["code"], "bad_frame_log") << run.err;

    run = run_sim("--frame-error " + write_log(frames_) + " " + temp_path("none.json"));
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_EQ(Json::parse(run.err, nullptr, false)["error"]["code"], "io_error") << run.err;

    const std::string not_journal = temp_path("not_journal.json");
    std::ofstream(not_journal) << "{\"format\": 1}";
    run = run_sim("--frame-error " + write_log(frames_) + " " + not_journal);
    EXPECT_EQ(run.exit_code, 2);
    EXPECT_TRUE(Json::parse(run.err, nullptr, false).contains("error")) << run.err;
}

} // namespace
} // namespace carrom::proto
