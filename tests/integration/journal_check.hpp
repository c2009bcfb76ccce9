#pragma once
// Checks a match journal as GET /matches/ID serves it: it decodes and replays clean through
// proto::replay (every stroke's ResultHash and recorded outcome, and the final state). In a file
// of its own: the journal's JSON and the wire codec cannot share a translation unit.

#include <string>

namespace carrom::integration {

struct JournalCheck {
    std::string problem; // empty when the journal decodes and replays clean
    int strokes = 0;
    int entries = 0;
    bool game_over = false;     // the last outcome ended the game
    bool turns_in_order = true; // each stroke's turn is greater than the previous one's
    // each stroke's or clock expiry's turn is the previous one's plus one, or plus two after
    // a board's end (rules::start_next_board takes a turn number): no turn lost, none played
    // twice
    bool turns_consecutive = true;
    int first_turn = -1; // the first stroke's or clock expiry's turn (-1: none)
    int last_turn = -1;  // the last one's
};

JournalCheck check_journal(const std::string& json_text);

} // namespace carrom::integration
