#include "carrom/room/outcome_messages.hpp"

#include "carrom/proto/limits.hpp"

namespace carrom::room {

proto::QueenInfo to_proto(const rules::QueenState& queen) {
    switch (queen.status) {
    case rules::QueenStatus::OnBoard:
        return {proto::QueenState::OnBoard, -1};
    case rules::QueenStatus::PendingCover:
        return {proto::QueenState::Pending, queen.seat};
    case rules::QueenStatus::Covered:
        return {proto::QueenState::Covered, queen.seat};
    case rules::QueenStatus::OutOfPlay:
        return {proto::QueenState::None, -1};
    }
    return {};
}

proto::Colour colour_of_team(const rules::MatchState& state, int team) {
    const auto colour = rules::team_colour(state, team);
    if (!colour) {
        return proto::Colour::None;
    }
    return *colour == BodyKind::White ? proto::Colour::White : proto::Colour::Black;
}

std::string_view rule_sentence(rules::RuleCode code) {
    using rules::RuleCode;
    switch (code) {
    case RuleCode::StrikerPocketed:
        return "The striker went into a pocket.";
    case RuleCode::QueenBeforeOwnCoin:
        return "The queen was pocketed before an own coin; it goes back to the centre.";
    case RuleCode::QueenNotCovered:
        return "The queen was not covered; it goes back to the centre.";
    case RuleCode::QueenCovered:
        return "The queen is covered.";
    case RuleCode::DuePaid:
        return "A coin came back to the centre to pay a due.";
    case RuleCode::OwnLastCoinBeforeQueen:
        return "The last own coin went in before the queen was covered.";
    case RuleCode::OpponentLastCoin:
        return "The opponent's last coin was pocketed.";
    case RuleCode::BreakMissed:
        return "The break did not touch a coin.";
    case RuleCode::ShotClockExpired:
        return "The shot clock ran out; the turn passes.";
    case RuleCode::MissedTurns:
        return "Too many turns were missed in a row: the game is lost.";
    case RuleCode::Forfeit:
        return "A player forfeited.";
    case RuleCode::BoardCleared:
        return "A side pocketed all its coins.";
    case RuleCode::ColourCleared:
        return "A colour is off the board.";
    case RuleCode::CoinsExhausted:
        return "No coins are left on the board.";
    case RuleCode::TargetPoints:
        return "A side reached the target score.";
    case RuleCode::BoardsPlayed:
        return "All boards have been played.";
    }
    return "A rule applied.";
}

std::string foul_sentence(const rules::Foul& foul, const rules::MatchState& after) {
    std::string sentence(rule_sentence(foul.code));
    const auto seat = static_cast<std::size_t>(foul.seat);
    if (foul.code != rules::RuleCode::ShotClockExpired || seat >= after.missed_turns.size() ||
        after.phase == rules::Phase::GameOver) {
        return sentence;
    }
    // The clock's misses in a row that still leave the game running (the next one at the limit
    // loses it): a stroke sets the count back to 0.
    const int left = after.config.missed_turns_to_lose - after.missed_turns[seat];
    if (left == 1) {
        return sentence + " One more missed turn in a row loses the game.";
    }
    return sentence + " " + std::to_string(left) + " more missed turns in a row lose the game.";
}

std::string_view game_end_reason(rules::RuleCode code) {
    using rules::RuleCode;
    switch (code) {
    case RuleCode::TargetPoints:
        return "score";
    case RuleCode::BoardsPlayed:
        return "boards";
    case RuleCode::Forfeit:
        return "forfeit";
    case RuleCode::MissedTurns:
    case RuleCode::ShotClockExpired:
        return "clock";
    default:
        return "cleared";
    }
}

proto::Error to_proto_error(const rules::RuleError& error) {
    using rules::RuleErrorCode;
    std::string_view code = proto::code::kIllegalShot;
    switch (error.code) {
    case RuleErrorCode::InvalidSeat:
    case RuleErrorCode::NotYourTurn:
        code = proto::code::kNotYourTurn;
        break;
    case RuleErrorCode::StaleTurn:
        code = proto::code::kStaleTurn;
        break;
    case RuleErrorCode::GameOver:
    case RuleErrorCode::BoardOver:
    case RuleErrorCode::WrongPhase:
        code = proto::code::kWrongPhase;
        break;
    case RuleErrorCode::XNotFinite:
    case RuleErrorCode::XOutOfRange:
    case RuleErrorCode::StrikerOverlaps:
        code = proto::code::kIllegalPlacement;
        break;
    case RuleErrorCode::AngleNotFinite:
    case RuleErrorCode::PowerNotFinite:
    case RuleErrorCode::PowerOutOfRange:
        code = proto::code::kIllegalShot;
        break;
    case RuleErrorCode::PhysicsError:
    case RuleErrorCode::InvalidConfig:
        code = proto::code::kInternal;
        break;
    }
    std::string message = error.message;
    if (message.size() > proto::kMaxTextBytes) {
        message.resize(proto::kMaxTextBytes);
    }
    return {std::string(code), std::move(message)};
}

std::vector<int> per_seat(const rules::MatchState& state, const std::vector<int>& per_team) {
    std::vector<int> out;
    for (std::size_t seat = 0; seat < state.seats.size(); ++seat) {
        const auto team = static_cast<std::size_t>(state.seats[seat].team);
        out.push_back(team < per_team.size() ? per_team[team] : 0);
    }
    return out;
}

proto::ShotResult to_shot_result(const rules::ShotOutcome& outcome,
                                 const rules::MatchState& after) {
    proto::ShotResult r;
    r.turn = outcome.turn_number;
    r.seat = outcome.seat;
    if (outcome.shot_taken) {
        r.x_px = outcome.shot.x_px;
        r.angle_rad = outcome.shot.angle_rad;
        r.power = outcome.shot.power;
    }
    r.pocketed = outcome.pocketed;
    if (outcome.striker_pocketed) {
        r.pocketed.push_back(kStrikerId);
    }
    for (const auto& piece : outcome.returned) {
        r.returned.push_back(piece.id);
    }
    for (const auto& foul : outcome.fouls) {
        r.fouls.push_back({std::string(rules::to_string(foul.code)), foul_sentence(foul, after)});
    }
    r.points = per_seat(after, outcome.score_changes);
    r.scores = per_seat(after, after.scores);
    r.dues = per_seat(after, after.dues_owed);
    r.queen = to_proto(outcome.queen_after);
    r.extra_turn = outcome.extra_stroke;
    r.next_turn = after.turn_number;
    r.next_seat = after.turn_seat;
    r.board_over = outcome.board_end.has_value();
    r.game_over = outcome.game_end.has_value();
    r.winner =
        outcome.game_end && outcome.game_end->winner_team ? *outcome.game_end->winner_team : -1;
    return r;
}

std::vector<proto::Event> rule_events(const rules::ShotOutcome& outcome,
                                      const rules::MatchState& before,
                                      const rules::MatchState& after) {
    std::vector<proto::Event> events;
    for (const auto& foul : outcome.fouls) {
        events.push_back(proto::FoulEvent{foul.seat, std::string(rules::to_string(foul.code)),
                                          foul_sentence(foul, after)});
    }
    if (outcome.queen_after.status != outcome.queen_before.status ||
        outcome.queen_after.seat != outcome.queen_before.seat) {
        events.push_back(proto::QueenEvent{to_proto(outcome.queen_after)});
    }
    const auto dues_before = per_seat(before, before.dues_owed);
    const auto dues_after = per_seat(after, after.dues_owed);
    for (std::size_t seat = 0; seat < dues_after.size() && seat < dues_before.size(); ++seat) {
        if (dues_after[seat] != dues_before[seat]) {
            events.push_back(proto::DueEvent{static_cast<int>(seat), dues_after[seat]});
        }
    }
    const auto scores = per_seat(after, after.scores);
    if (outcome.board_end) {
        events.push_back(proto::BoardEndEvent{outcome.board_end->board,
                                              outcome.board_end->winner_team.value_or(-1),
                                              outcome.board_end->points, scores});
    }
    if (outcome.game_end) {
        events.push_back(
            proto::GameEndEvent{outcome.game_end->winner_team.value_or(-1),
                                std::string(game_end_reason(outcome.game_end->reason)), scores,
                                std::string(rules::to_string(outcome.game_end->reason))});
    }
    return events;
}

} // namespace carrom::room
