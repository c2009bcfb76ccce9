#include "carrom/rules/match.hpp"

#include "stroke.hpp"

#include <string>

namespace carrom::rules {
namespace {

std::vector<Body> board_layout(RuleSet rule_set, const PhysicsConfig& physics) {
    std::vector<Body> bodies = standard_layout(physics);
    if (rule_set == RuleSet::DiscPool) {
        for (Body& body : bodies) {
            if (body.id == kQueenId) {
                body.pocketed = true; // out of play
            }
        }
    }
    return bodies;
}

QueenState initial_queen(RuleSet rule_set) {
    return rule_set == RuleSet::DiscPool ? QueenState{QueenStatus::OutOfPlay, -1} : QueenState{};
}

void reset_board(MatchState& st, int breaker) {
    st.bodies = board_layout(st.rule_set, st.physics);
    st.pocketed.clear();
    st.dues_owed.assign(st.dues_owed.size(), 0);
    st.breaker = breaker;
    st.turn_seat = breaker;
    st.strokes_this_board = 0;
    st.break_tries = 0;
    st.break_done = false;
    st.queen = initial_queen(st.rule_set);
    st.phase = Phase::AwaitingShot;
}

} // namespace

MatchState new_match(RuleSet rule_set, const RulesConfig& rules, const PhysicsConfig& physics) {
    MatchState st;
    st.rule_set = rule_set;
    st.config = rules;
    st.physics = physics;
    st.seats = make_seats(rules.seat_count);
    const auto teams = static_cast<std::size_t>(team_count(rules.seat_count));
    st.scores.assign(teams, 0);
    st.dues_owed.assign(teams, 0);
    st.missed_turns.assign(st.seats.size(), 0);
    st.board = 1;
    reset_board(st, rules.first_breaker);
    return st;
}

MatchState start_next_board(const MatchState& state) {
    MatchState st = state;
    if (st.phase != Phase::BoardOver) {
        return st;
    }
    st.board += 1;
    reset_board(st, next_seat(state.breaker, st.config.seat_count));
    st.turn_number += 1;
    return st;
}

std::optional<RuleError> check_turn(const MatchState& state, int seat,
                                    std::optional<int> turn_number) {
    if (seat < 0 || seat >= static_cast<int>(state.seats.size())) {
        return RuleError{RuleErrorCode::InvalidSeat, "seat",
                         "There is no seat " + std::to_string(seat) + "."};
    }
    if (state.phase == Phase::GameOver) {
        return RuleError{RuleErrorCode::GameOver, "", "The game is over."};
    }
    if (state.phase == Phase::BoardOver) {
        return RuleError{RuleErrorCode::BoardOver, "",
                         "The board is over; the next one has not started."};
    }
    if (seat != state.turn_seat) {
        return RuleError{RuleErrorCode::NotYourTurn, "seat",
                         "It is seat " + std::to_string(state.turn_seat) + "'s turn."};
    }
    if (turn_number && *turn_number != state.turn_number) {
        return RuleError{RuleErrorCode::StaleTurn, "turn",
                         "That input was for turn " + std::to_string(*turn_number) +
                             "; the turn is " + std::to_string(state.turn_number) + "."};
    }
    return std::nullopt;
}

StrokePhysics stroke_physics_from(const SimResult& result) {
    // From the summaries the engine always fills, so the event list need not be recorded.
    StrokePhysics physics;
    physics.bodies = result.bodies;
    physics.pocket_order = result.pocket_order;
    physics.striker_touched_coin = false;
    for (std::size_t i = 0; i < result.bodies.size(); ++i) {
        if (result.bodies[i].id != kStrikerId) {
            continue;
        }
        physics.striker_pocketed = result.bodies[i].pocketed;
        physics.striker_touched_coin =
            i < result.collision_counts.size() && result.collision_counts[i] > 0;
    }
    return physics;
}

StrokeResult judge_stroke(const MatchState& state, int seat, const Shot& shot,
                          const StrokePhysics& physics) {
    detail::Stroke s = detail::begin_stroke(state, seat, shot, physics);
    bool extra = false;
    switch (state.rule_set) {
    case RuleSet::Icf:
        extra = detail::judge_icf(s);
        break;
    case RuleSet::Seed:
        extra = detail::judge_seed(s);
        break;
    case RuleSet::Freestyle:
        extra = detail::judge_freestyle(s);
        break;
    case RuleSet::DiscPool:
        extra = detail::judge_discpool(s);
        break;
    }
    return detail::finish_stroke(s, extra);
}

PlayResult play_shot(const MatchState& state, int seat, const Shot& shot, ExactEngine& engine,
                     const PlayOptions& options) {
    PlayResult out;
    out.error = check_turn(state, seat);
    if (!out.error) {
        out.error = check_placement(state, seat, shot);
    }
    if (out.error) {
        out.state = state;
        return out;
    }
    std::vector<Body> bodies = state.bodies;
    bodies.push_back(
        striker_for(state.physics, state.seats[static_cast<std::size_t>(seat)].side, shot));
    SimOptions sim;
    sim.record_events = true;
    sim.record_trajectory = options.record_trajectory;
    const ExactEngine::Outcome run = engine.run(bodies, sim);
    if (run.error || run.result == nullptr) {
        out.error = RuleError{RuleErrorCode::PhysicsError, run.error ? run.error->field : "",
                              run.error ? run.error->message : "The simulation failed."};
        out.state = state;
        return out;
    }
    StrokeResult judged = judge_stroke(state, seat, shot, stroke_physics_from(*run.result));
    out.state = std::move(judged.state);
    out.outcome = std::move(judged.outcome);
    out.outcome.physics = *run.result;
    return out;
}

} // namespace carrom::rules
