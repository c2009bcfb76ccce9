// Shot clock and forfeit: turns that end without a stroke.

#include "carrom/rules/match.hpp"

#include "stroke.hpp"

namespace carrom::rules {
namespace {

detail::Stroke begin_non_stroke(const MatchState& state, int seat) {
    detail::Stroke s;
    s.state = state;
    s.seat = seat;
    s.team = team_of(state, seat);
    s.scores_before = state.scores;
    s.outcome.seat = seat;
    s.outcome.turn_number = state.turn_number;
    s.outcome.queen_before = state.queen;
    return s;
}

} // namespace

bool shot_clock_ran_out(const MatchState& state, double elapsed_s) {
    return state.config.shot_clock_s > 0.0 &&
           elapsed_s > state.config.shot_clock_s + state.config.shot_clock_grace_s;
}

PlayResult shot_clock_expired(const MatchState& state, int seat) {
    PlayResult out;
    out.error = check_turn(state, seat);
    if (out.error) {
        out.state = state;
        return out;
    }
    detail::Stroke s = begin_non_stroke(state, seat);
    detail::add_foul(s, RuleCode::ShotClockExpired);
    if (state.queen.status == QueenStatus::PendingCover && state.queen.seat == seat) {
        detail::return_queen(s, RuleCode::QueenNotCovered);
    }
    int& missed = s.state.missed_turns[static_cast<std::size_t>(seat)];
    missed += 1;
    if (missed >= state.config.missed_turns_to_lose) {
        detail::add_foul(s, RuleCode::MissedTurns);
        detail::end_game(s.state, s.outcome, detail::other_team(s.team), RuleCode::MissedTurns);
    }
    StrokeResult done = detail::finish_stroke(s, false);
    out.state = std::move(done.state);
    out.outcome = std::move(done.outcome);
    return out;
}

PlayResult forfeit(const MatchState& state, int seat) {
    PlayResult out;
    if (seat < 0 || seat >= static_cast<int>(state.seats.size())) {
        out.error = RuleError{RuleErrorCode::InvalidSeat, "seat",
                              "There is no seat " + std::to_string(seat) + "."};
    } else if (state.phase == Phase::GameOver) {
        out.error = RuleError{RuleErrorCode::GameOver, "", "The game is over."};
    }
    if (out.error) {
        out.state = state;
        return out;
    }
    detail::Stroke s = begin_non_stroke(state, seat);
    detail::add_foul(s, RuleCode::Forfeit);
    detail::end_game(s.state, s.outcome, detail::other_team(s.team), RuleCode::Forfeit);
    StrokeResult done = detail::finish_stroke(s, false);
    out.state = std::move(done.state);
    out.outcome = std::move(done.outcome);
    return out;
}

} // namespace carrom::rules
