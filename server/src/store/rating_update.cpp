#include "store/rating_update.hpp"

#include "carrom/ratings/glicko2.hpp"

namespace carrom::store {

namespace {

ratings::Rating aged_rating(const RatedSeat& seat, std::int64_t time_ms) {
    if (!seat.stored) {
        return ratings::Rating{};
    }
    const std::int64_t idle_periods = (time_ms - seat.stored->last_game_ms) / kRatingPeriodMs;
    return ratings::Glicko2{}.age(seat.stored->rating, idle_periods);
}

} // namespace

std::array<RatingOutcome, 2> rate_singles_game(const std::array<RatedSeat, 2>& seats,
                                               rules::RuleSet rule_set,
                                               const rules::GameResult& result,
                                               std::int64_t time_ms) {
    const std::array<ratings::Rating, 2> before{aged_rating(seats[0], time_ms),
                                                aged_rating(seats[1], time_ms)};
    std::array<RatingOutcome, 2> out;
    for (std::size_t seat = 0; seat < 2; ++seat) {
        const double score = !result.winner_team                             ? 0.5
                             : *result.winner_team == static_cast<int>(seat) ? 1.0
                                                                             : 0.0;
        const ratings::GameScore game{before[1 - seat], score};
        RatingOutcome& o = out[seat];
        o.player = seats[seat].player;
        o.before = before[seat];
        o.score = score;
        o.after = seats[seat].stored.value_or(PlayerRating{});
        o.after.rule_set = rule_set;
        o.after.rating = ratings::Glicko2{}.rate(before[seat], std::span(&game, 1));
        o.after.games += 1;
        o.after.wins += score == 1.0 ? 1 : 0;
        o.after.losses += score == 0.0 ? 1 : 0;
        o.after.draws += score == 0.5 ? 1 : 0;
        o.after.last_game_ms = time_ms;
    }
    return out;
}

} // namespace carrom::store
