#include "carrom/bots/arena.hpp"

namespace carrom::bots {

namespace {

// One stroke by seat with its strategy; refused shots are retried, then the seat forfeits.
rules::PlayResult play_turn(const rules::MatchState& state, int seat, Strategy& player,
                            ExactEngine& engine, const ArenaOptions& options, SeatRecord& record) {
    for (int refusal = 0; refusal <= options.max_refusals; ++refusal) {
        const Strategy::SearchTotals before = player.search_totals();
        const Shot shot = player.choose_shot(state, seat, options.budget);
        const Strategy::SearchTotals after = player.search_totals();
        record.candidates += after.candidates - before.candidates;
        record.think_s += after.seconds - before.seconds;
        rules::PlayResult result = rules::play_shot(state, seat, shot, engine);
        if (!result.error) {
            return result;
        }
        ++record.refusals;
        player.shot_refused();
    }
    return rules::forfeit(state, seat);
}

} // namespace

GameRecord play_game(const rules::MatchState& start, const std::vector<Strategy*>& players,
                     const ArenaOptions& options) {
    GameRecord record;
    record.seats.resize(start.seats.size());
    if (players.size() != start.seats.size()) {
        return record;
    }
    rules::MatchState state = start;
    ExactEngine engine(state.physics);
    int strokes = 0;
    while (state.phase != rules::Phase::GameOver && strokes < options.max_strokes) {
        if (state.phase == rules::Phase::BoardOver) {
            state = rules::start_next_board(state);
            continue;
        }
        const int seat = state.turn_seat;
        SeatRecord& seat_record = record.seats[static_cast<std::size_t>(seat)];
        rules::PlayResult result = play_turn(state, seat, *players[static_cast<std::size_t>(seat)],
                                             engine, options, seat_record);
        if (result.outcome.shot_taken) {
            ++seat_record.strokes;
            ++strokes;
            seat_record.fouls += result.outcome.fouls.empty() ? 0 : 1;
            seat_record.pocketed += static_cast<int>(result.outcome.pocketed.size());
        }
        state = std::move(result.state);
    }
    record.boards = state.board;
    record.scores = state.scores;
    if (state.phase == rules::Phase::GameOver && state.result) {
        record.finished = true;
        record.reason = state.result->reason;
        record.winner_team = state.result->winner_team;
    }
    return record;
}

} // namespace carrom::bots
