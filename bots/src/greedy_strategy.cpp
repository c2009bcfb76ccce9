#include "carrom/bots/greedy_strategy.hpp"

#include "carrom/bots/shot_geometry.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace carrom::bots {

namespace {

using Clock = std::chrono::steady_clock;

// Cumulative shares of the decision budget at which each phase ends.
constexpr double kCoarseShare = 0.55;
constexpr double kRefineShare = 0.75;

// Two candidates closer than this in every parameter count as the same shot in the best list.
constexpr double kSameAngleRad = 0.2 * std::numbers::pi / 180.0;
constexpr double kSamePower = 0.25;
constexpr double kSameXPx = 1.0;

// First refinement steps (halved every round).
constexpr double kRefineAngleRad = 0.6 * std::numbers::pi / 180.0;
constexpr double kRefinePowerFraction = 0.10;
constexpr double kRefineXPx = 6.0;

bool same_shot(const Shot& a, const Shot& b) {
    return std::abs(a.angle_rad - b.angle_rad) < kSameAngleRad &&
           std::abs(a.power - b.power) < kSamePower && std::abs(a.x_px - b.x_px) < kSameXPx;
}

// The best `capacity` distinct candidates, best first.
class BestList {
public:
    explicit BestList(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

    void offer(const RatedShot& rated) {
        for (std::size_t i = 0; i < best_.size(); ++i) {
            if (same_shot(best_[i].shot, rated.shot)) {
                if (rank_above(rated, best_[i])) {
                    best_.erase(best_.begin() + static_cast<std::ptrdiff_t>(i));
                    break;
                }
                return;
            }
        }
        const auto at = std::find_if(best_.begin(), best_.end(),
                                     [&](const RatedShot& b) { return rank_above(rated, b); });
        best_.insert(at, rated);
        if (best_.size() > capacity_) {
            best_.pop_back();
        }
    }
    const std::vector<RatedShot>& shots() const { return best_; }

private:
    std::size_t capacity_;
    std::vector<RatedShot> best_;
};

// One decision's search: the evaluator, the budget, the best candidates so far.
class Search {
public:
    Search(StrokeEvaluator& evaluator, const DecisionBudget& budget, std::size_t keep)
        : evaluator_(evaluator), start_(Clock::now()), budget_(budget), best_(keep) {}

    // Sets the limit of the current phase: share of the whole budget, counted from the start.
    void phase_ends_at(double share) {
        until_ = start_ + std::chrono::duration_cast<Clock::duration>(budget_.time * share);
        limit_ = std::max<std::int64_t>(
            1, static_cast<std::int64_t>(share * static_cast<double>(budget_.max_candidates)));
    }
    // True while the current phase may simulate another candidate (the first one always may).
    bool may_continue() {
        if (evaluator_.evaluated() == 0) {
            return true;
        }
        if (evaluator_.evaluated() >= limit_) {
            return false;
        }
        if (Clock::now() >= until_) {
            out_of_time_ = true;
            return false;
        }
        return true;
    }
    RatedShot rate(const Shot& shot) {
        const RatedShot rated = evaluator_.evaluate(shot);
        best_.offer(rated);
        return rated;
    }
    StrokeEvaluator& evaluator() { return evaluator_; }
    const BestList& best() const { return best_; }
    bool out_of_time() const { return out_of_time_; }
    double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

private:
    StrokeEvaluator& evaluator_;
    Clock::time_point start_;
    DecisionBudget budget_;
    Clock::time_point until_{};
    std::int64_t limit_ = 1;
    bool out_of_time_ = false;
    BestList best_;
};

void coarse_phase(Search& search, const GreedyOptions& options) {
    const StrokeEvaluator& evaluator = search.evaluator();
    const rules::MatchState& state = evaluator.state();
    const int seat = evaluator.seat();
    const std::vector<double> aim_xs = legal_baseline_xs(evaluator, options.aim_positions);
    const std::vector<double> grid_xs = legal_baseline_xs(evaluator, options.grid_positions);
    for (const auto& shots : {aimed_shots(state, seat, aim_xs, options.aim),
                              grid_shots(state, seat, grid_xs, options.grid)}) {
        for (const Shot& shot : shots) {
            if (!search.may_continue()) {
                return;
            }
            search.rate(shot);
        }
    }
}

// Neighbours of a shot one step away in angle, power and (legal) striker position.
std::vector<Shot> neighbours(const StrokeEvaluator& evaluator, const Shot& shot, double scale) {
    const PhysicsConfig& physics = evaluator.state().physics;
    const double angle_step = kRefineAngleRad * scale;
    const double power_step = kRefinePowerFraction * scale * std::max(shot.power, 1.0);
    const double x_step = kRefineXPx * scale;
    std::vector<Shot> out{
        Shot{shot.x_px, shot.angle_rad + angle_step, shot.power},
        Shot{shot.x_px, shot.angle_rad - angle_step, shot.power},
        Shot{shot.x_px, shot.angle_rad, std::min(shot.power + power_step, physics.max_power)},
        Shot{shot.x_px, shot.angle_rad, std::max(shot.power - power_step, 0.0)},
    };
    const BaselineRange range = baseline_range(evaluator.state());
    for (const double x : {shot.x_px + x_step, shot.x_px - x_step}) {
        if (x >= range.min_px && x <= range.max_px && evaluator.placement_legal(x)) {
            out.push_back(Shot{x, shot.angle_rad, shot.power});
        }
    }
    return out;
}

void refine_phase(Search& search, const GreedyOptions& options) {
    std::vector<RatedShot> seeds = search.best().shots();
    seeds.resize(std::min(seeds.size(), static_cast<std::size_t>(options.refine_seeds)));
    for (RatedShot current : seeds) {
        double scale = 1.0;
        for (int round = 0; round < options.refine_rounds; ++round, scale *= 0.5) {
            for (const Shot& next : neighbours(search.evaluator(), current.shot, scale)) {
                if (!search.may_continue()) {
                    return;
                }
                const RatedShot rated = search.rate(next);
                if (rank_above(rated, current)) {
                    current = rated;
                }
            }
        }
    }
}

// The best few replayed with the bot's own noise: the one with the best mean score wins among
// those without a foul when played as intended. Returns the candidates ranked by that.
std::vector<RatedShot> robust_phase(Search& search, const GreedyOptions& options,
                                    const ExecutionNoise& noise, std::mt19937_64& rng) {
    std::vector<RatedShot> ranked = search.best().shots();
    if (noise.angle_sigma_rad <= 0.0 && noise.power_sigma_fraction <= 0.0) {
        return ranked;
    }
    ranked.resize(std::min(ranked.size(), static_cast<std::size_t>(options.robust_shots)));
    const double max_power = search.evaluator().state().physics.max_power;
    for (RatedShot& candidate : ranked) {
        double total = candidate.score;
        int played = 1;
        for (int r = 0; r < options.robust_replays && search.may_continue(); ++r) {
            const Shot noisy = execute_with_noise(candidate.shot, noise, max_power, rng);
            total += search.evaluator().evaluate(noisy).score;
            ++played;
        }
        candidate.score = total / static_cast<double>(played);
    }
    std::stable_sort(ranked.begin(), ranked.end(), rank_above);
    return ranked;
}

} // namespace

GreedyStrategy::GreedyStrategy(GreedyOptions options)
    : options_(std::move(options)), noise_(noise_of(options_.level)), rng_(options_.seed) {}

Shot GreedyStrategy::choose_shot(const rules::MatchState& state, int seat,
                                 const DecisionBudget& budget) {
    if (state.turn_number != last_turn_) {
        refusals_ = 0;
        last_turn_ = state.turn_number;
    }
    StrokeEvaluator evaluator(state, seat, options_.weights);
    const std::size_t keep = static_cast<std::size_t>(
        std::max({options_.refine_seeds, options_.robust_shots, 1}) + refusals_);
    Search search(evaluator, budget, keep);
    search.phase_ends_at(kCoarseShare);
    coarse_phase(search, options_);
    search.phase_ends_at(kRefineShare);
    refine_phase(search, options_);
    search.phase_ends_at(1.0);
    const std::vector<RatedShot> ranked = robust_phase(search, options_, noise_, rng_);

    last_ = DecisionStats{};
    last_.candidates = evaluator.evaluated();
    last_.seconds = search.seconds();
    last_.candidates_per_s =
        last_.seconds > 0.0 ? static_cast<double>(last_.candidates) / last_.seconds : 0.0;
    last_.out_of_time = search.out_of_time();
    totals_.candidates += last_.candidates;
    totals_.seconds += last_.seconds;
    if (ranked.empty()) { // the whole baseline is blocked: nothing legal to find
        last_.executed = Shot{baseline_range(state).min_px, forward_angle(state, seat), 0.0};
        return last_.executed;
    }
    // After a refusal, the next best (the server saw a different state than we did).
    last_.chosen = ranked[std::min(ranked.size() - 1, static_cast<std::size_t>(refusals_))];
    last_.executed = execute_with_noise(last_.chosen.shot, noise_, state.physics.max_power, rng_);
    return last_.executed;
}

} // namespace carrom::bots
