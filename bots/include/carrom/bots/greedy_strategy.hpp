#pragma once
// "greedy": a one-stroke search with the exact engine and the rules.
//   1. coarse: aimed shots (ghost-ball shots at every wanted coin into every pocket, from
//      aim_positions striker positions) and a grid (grid_positions x angle x power);
//   2. refine: hill-climb the best few in angle, power and position with shrinking steps;
//   3. robust: with execution noise, rate the best few by their mean over noisy replays of
//      that noise, so the bot prefers shots it can make;
// then plays the best (never a foul when a stroke without one was found), with its level's
// execution noise. Each phase stops at its share of the DecisionBudget (time and candidates);
// deterministic for a seed whenever the candidate limit, not the clock, ends the search.

#include "carrom/bots/shot_candidates.hpp"
#include "carrom/bots/skill.hpp"
#include "carrom/bots/strategy.hpp"
#include "carrom/bots/stroke_evaluator.hpp"

#include <cstdint>
#include <random>

namespace carrom::bots {

struct GreedyOptions {
    SkillLevel level = SkillLevel::Hard;
    std::uint64_t seed = 1;
    int aim_positions = 25; // striker positions for aimed shots
    int grid_positions = 9; // striker positions for the grid
    GridSpec grid{};
    AimSpec aim{};
    int refine_seeds = 8;    // best distinct candidates hill-climbed
    int refine_rounds = 4;   // step halvings
    int robust_shots = 6;    // best candidates replayed with noise
    int robust_replays = 10; // noisy replays each
    ValueWeights weights{};
};

// What the last decision did.
struct DecisionStats {
    std::int64_t candidates = 0; // strokes simulated
    double seconds = 0.0;        // wall time of the decision
    double candidates_per_s = 0.0;
    bool out_of_time = false; // the time budget ended the search
    RatedShot chosen{};       // the intended shot and its (noise-free) rating
    Shot executed{};          // the shot played, after execution noise
};

class GreedyStrategy final : public Strategy {
public:
    explicit GreedyStrategy(GreedyOptions options);
    std::string_view name() const override { return "greedy"; }
    Shot choose_shot(const rules::MatchState& state, int seat,
                     const DecisionBudget& budget) override;
    void shot_refused() override { ++refusals_; }
    SearchTotals search_totals() const override { return totals_; }

    const DecisionStats& last_decision() const { return last_; }
    const GreedyOptions& options() const { return options_; }

private:
    GreedyOptions options_;
    ExecutionNoise noise_;
    std::mt19937_64 rng_;
    DecisionStats last_;
    SearchTotals totals_;
    int refusals_ = 0;   // refusals of shots chosen for last_turn_
    int last_turn_ = -1; // turn number of the last decision
};

} // namespace carrom::bots
