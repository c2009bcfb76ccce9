#pragma once
// Simulates candidate strokes for one decision and rates them: the exact engine for the physics,
// the rules (judge_stroke) for the outcome, position_value for the score. One evaluator per
// decision: it keeps the scene buffer and the engine between candidates, so a candidate costs
// one simulation and one rules judgement, nothing else.

#include "carrom/bots/position_value.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace carrom::bots {

// A candidate and what it was rated. Ranked by rank_above: a stroke without a foul always
// ranks above one with a foul (a bot never fouls by choice), then the higher score.
struct RatedShot {
    Shot shot{};
    bool foul = true;                                        // the outcome has a foul
    double score = -std::numeric_limits<double>::infinity(); // stroke score, larger is better
};

bool rank_above(const RatedShot& a, const RatedShot& b);

class StrokeEvaluator {
public:
    // state must be AwaitingShot with seat to play (check_turn finds nothing). The evaluator
    // keeps a reference to state: state must outlive it.
    StrokeEvaluator(const rules::MatchState& state, int seat, const ValueWeights& weights = {});

    // True when the rules accept the striker at x_px on the seat's baseline.
    bool placement_legal(double x_px) const;

    // Simulates the shot and rates it. Precondition: placement_legal(shot.x_px), finite angle,
    // power in [0, max_power]. A shot the engine rejects (it cannot happen for a legal
    // placement) is rated as a foul with score -infinity.
    RatedShot evaluate(const Shot& shot);

    // The rules' result of a shot (as rules::play_shot gives it, without the physics record),
    // or nothing when the engine rejects the scene.
    std::optional<rules::StrokeResult> judge(const Shot& shot);

    const rules::MatchState& state() const { return state_; }
    int seat() const { return seat_; }
    std::int64_t evaluated() const { return evaluated_; } // evaluate() calls so far

private:
    const rules::MatchState& state_;
    int seat_ = 0;
    int team_ = 0;
    ValueWeights weights_;
    double value_before_ = 0.0;
    ExactEngine engine_;
    std::vector<Body> scene_; // state's pieces plus the striker (last)
    std::int64_t evaluated_ = 0;
};

} // namespace carrom::bots
