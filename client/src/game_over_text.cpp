#include "carrom/client/game_over_text.hpp"

namespace carrom::client {
namespace {

// The other seat of a two-seat room (the one that did not win), -1 if there is none.
int other_seat(const MatchView& v, int seat) {
    if (seat < 0 || v.seats.size() != 2) {
        return -1;
    }
    return 1 - seat;
}

std::string name(const MatchView& v, int seat) {
    return player_name_at_end(v, seat);
}

// "You" or the seat's name, to start a sentence.
std::string subject(const MatchView& v, int seat) {
    return seat == v.you ? "You" : name(v, seat);
}

// "you have" / "Ana has": who leads on points, or that the scores are level.
std::string who_leads(const MatchView& v, int winner) {
    if (winner < 0) {
        return "the scores are level";
    }
    return winner == v.you ? "you have more points" : name(v, winner) + " has more points";
}

std::string cleared_reason(const MatchView& v, int winner) {
    switch (v.rule_set) {
    case proto::RuleSet::Seed:
        return "A colour is off the board and " + who_leads(v, winner) + ".";
    case proto::RuleSet::Freestyle:
        return "No coins are left on the board and " + who_leads(v, winner) + ".";
    case proto::RuleSet::DiscPool:
        if (winner < 0) {
            return "The coins are off the board.";
        }
        return winner == v.you ? std::string("All your coins are off the board.")
                               : "All of " + name(v, winner) + "'s coins are off the board.";
    case proto::RuleSet::Icf:
        break;
    }
    return winner < 0 ? "The board is cleared." : subject(v, winner) + " cleared the board.";
}

std::string reason_sentence(const MatchView& v, const GameResult& r) {
    const int loser = other_seat(v, r.winner);
    if (r.reason == "score" && r.winner >= 0) {
        return subject(v, r.winner) + " reached " + std::to_string(v.options.target_points) +
               " points.";
    }
    if (r.reason == "boards") {
        const std::string played =
            v.options.boards == 1
                ? std::string("The board is played")
                : "All " + std::to_string(v.options.boards) + " boards are played";
        return played + " and " + who_leads(v, r.winner) + ".";
    }
    if (r.reason == "cleared") {
        return cleared_reason(v, r.winner);
    }
    if (loser >= 0 && r.reason == "clock") {
        return subject(v, loser) + " let the shot clock run out three times in a row.";
    }
    if (loser >= 0 && r.reason == "forfeit") {
        return subject(v, loser) + " lost the connection and did not come back in time.";
    }
    if (loser >= 0 && r.reason == "left") {
        return subject(v, loser) + " left the game.";
    }
    if (r.reason.empty()) {
        return "The game is over.";
    }
    return "The game is over (" + r.reason + ").";
}

std::string title(const MatchView& v, int winner) {
    if (winner < 0) {
        return "A draw";
    }
    if (winner == v.you) {
        return "You won!";
    }
    return v.you >= 0 ? "You lost" : name(v, winner) + " won";
}

std::string score_line(const MatchView& v, const GameResult& r) {
    std::string out = "Final score: ";
    const int n = static_cast<int>(r.scores.size());
    const int first = v.you >= 0 && v.you < n ? v.you : 0;
    for (int i = 0; i < n; ++i) {
        const int seat = (first + i) % n;
        out += (i > 0 ? ", " : "") + name(v, seat) + " " +
               std::to_string(r.scores[static_cast<std::size_t>(seat)]);
    }
    return out;
}

} // namespace

GameOverText game_over_text(const MatchView& view, bool rematch_asked) {
    GameOverText out;
    GameResult result = view.result.value_or(GameResult{view.winner, "", {}, {}});
    if (result.scores.empty()) {
        for (const SeatView& s : view.seats) {
            result.scores.push_back(s.score);
        }
    }
    out.title = title(view, result.winner);
    out.reason = reason_sentence(view, result);
    out.score = score_line(view, result);
    const bool seated = view.you >= 0;
    out.can_rematch = seated && !rematch_asked;
    if (seated && rematch_asked) {
        const int other = other_seat(view, view.you);
        const bool empty = other < 0 || !view.seats[static_cast<std::size_t>(other)].occupied;
        out.waiting = empty ? "Waiting for a player to join the room"
                            : "Waiting for " + seat_name(view, other) + " to agree to a rematch";
    }
    return out;
}

} // namespace carrom::client
