#include "carrom/bots/stroke_evaluator.hpp"

#include "carrom/rules/placement.hpp"

namespace carrom::bots {

bool rank_above(const RatedShot& a, const RatedShot& b) {
    if (a.foul != b.foul) {
        return !a.foul;
    }
    return a.score > b.score;
}

StrokeEvaluator::StrokeEvaluator(const rules::MatchState& state, int seat,
                                 const ValueWeights& weights)
    : state_(state), seat_(seat), team_(rules::team_of(state, seat)), weights_(weights),
      value_before_(position_value(state, team_, weights)), engine_(state.physics),
      scene_(state.bodies) {
    scene_.push_back(Body{});
}

bool StrokeEvaluator::placement_legal(double x_px) const {
    return !rules::check_placement(state_, seat_, Shot{x_px, 0.0, 0.0}).has_value();
}

std::optional<rules::StrokeResult> StrokeEvaluator::judge(const Shot& shot) {
    const rules::Side side = state_.seats[static_cast<std::size_t>(seat_)].side;
    scene_.back() = rules::striker_for(state_.physics, side, shot);
    SimOptions options;
    options.record_events = false; // the rules read only the summaries (pocket order, contacts)
    const ExactEngine::Outcome run = engine_.run(scene_, options);
    if (run.error || run.result == nullptr) {
        return std::nullopt;
    }
    return rules::judge_stroke(state_, seat_, shot, rules::stroke_physics_from(*run.result));
}

RatedShot StrokeEvaluator::evaluate(const Shot& shot) {
    ++evaluated_;
    const std::optional<rules::StrokeResult> result = judge(shot);
    RatedShot rated;
    rated.shot = shot;
    if (!result) {
        return rated; // a foul with score -infinity: never chosen over a simulated stroke
    }
    rated.foul = !result->outcome.fouls.empty();
    rated.score = position_value(result->state, team_, weights_) - value_before_ +
                  turn_value(result->state, team_, weights_);
    return rated;
}

} // namespace carrom::bots
