#include "carrom/client/board_summary_text.hpp"

#include "carrom/client/plain_words.hpp"

#include <cctype>

namespace carrom::client {
namespace {

bool our_team(const MatchView& v, int team) {
    return v.you >= 0 && team >= 0 && team == team_of(v, v.you);
}

// "you" for our team (a pair: "your team"), else the team's players.
std::string who(const MatchView& v, int team) {
    if (our_team(v, team)) {
        return v.seats.size() == 4 ? "your team" : "you";
    }
    return team_subject(v, team);
}

} // namespace

BoardSummaryText board_summary_text(const MatchView& view) {
    BoardSummaryText out;
    const BoardSummary summary = view.board_summary.value_or(BoardSummary{});
    const std::string board = "board " + std::to_string(summary.board);
    if (summary.winner < 0) {
        out.title = "Board " + std::to_string(summary.board) + ": no winner";
    } else {
        std::string winner = who(view, summary.winner);
        winner[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(winner[0])));
        out.title = winner + " won " + board;
    }
    // The score, our team first (seat 0's team first for a spectator).
    const int teams = view.seats.size() == 4 ? 2 : static_cast<int>(view.seats.size());
    const int first = view.you >= 0 ? team_of(view, view.you) : 0;
    std::string score;
    for (int i = 0; i < teams; ++i) {
        const int team = (first + i) % teams;
        score += (i > 0 ? ", " : "") + who(view, team) + " " +
                 std::to_string(view.seats[static_cast<std::size_t>(team)].score);
    }
    out.points = (summary.points > 0 ? "+" + count_words(summary.points, "point", "points") + ". "
                                     : std::string()) +
                 "Score: " + score;
    if (view.you >= 0 && static_cast<std::size_t>(view.you) < view.seats.size()) {
        const proto::Colour colour = view.seats[static_cast<std::size_t>(view.you)].colour;
        if (colour != proto::Colour::None) {
            out.colours = "Board " + std::to_string(view.board_number) + ": " +
                          (view.seats.size() == 4 ? "your team plays " : "you play ") +
                          std::string(proto::to_string(colour));
        }
    }
    return out;
}

} // namespace carrom::client
