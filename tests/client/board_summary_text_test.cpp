// The card between two boards in words, from each reader's side.
#include "carrom/client/board_summary_text.hpp"

#include <gtest/gtest.h>

namespace carrom::client {
namespace {

MatchView after_board(int you, int seats, int winner, int points) {
    MatchView v;
    v.in_room = true;
    v.you = you;
    v.board_number = 2;
    const char* names[] = {"Asha", "Ravi", "Cy", "Dee"};
    v.seats.resize(static_cast<std::size_t>(seats));
    for (int i = 0; i < seats; ++i) {
        SeatView& s = v.seats[static_cast<std::size_t>(i)];
        s.occupied = true;
        s.name = names[i];
        s.colour = (i % 2 == 0) ? proto::Colour::Black : proto::Colour::White;
        s.score = (i % 2 == 0) ? 3 : 7;
    }
    v.board_summary = BoardSummary{1, winner, points, 0.0};
    return v;
}

TEST(BoardSummaryText, TheWinnerSeesTheirWinAndNewColour) {
    EXPECT_EQ(board_summary_text(after_board(0, 2, 0, 3)),
              (BoardSummaryText{"You won board 1", "+3 points. Score: you 3, Ravi 7",
                                "Board 2: you play black"}));
}

TEST(BoardSummaryText, TheOtherSideReadsItFromTheirs) {
    EXPECT_EQ(board_summary_text(after_board(1, 2, 0, 1)),
              (BoardSummaryText{"Asha won board 1", "+1 point. Score: you 7, Asha 3",
                                "Board 2: you play white"}));
}

TEST(BoardSummaryText, ASpectatorGetsNamesAndNoColour) {
    EXPECT_EQ(board_summary_text(after_board(-1, 2, 1, 4)),
              (BoardSummaryText{"Ravi won board 1", "+4 points. Score: Asha 3, Ravi 7", ""}));
}

TEST(BoardSummaryText, DoublesNamesTeams) {
    EXPECT_EQ(
        board_summary_text(after_board(2, 4, 1, 2)),
        (BoardSummaryText{"Ravi & Dee won board 1", "+2 points. Score: your team 3, Ravi & Dee 7",
                          "Board 2: your team plays black"}));
    EXPECT_EQ(board_summary_text(after_board(1, 4, 1, 2)).title, "Your team won board 1");
}

TEST(BoardSummaryText, FreestyleAndNoWinner) {
    MatchView v = after_board(0, 2, -1, 0);
    v.seats[0].colour = proto::Colour::None;
    EXPECT_EQ(board_summary_text(v),
              (BoardSummaryText{"Board 1: no winner", "Score: you 3, Ravi 7", ""}));
}

} // namespace
} // namespace carrom::client
