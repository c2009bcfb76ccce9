#include "journal_check.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/journal_replay.hpp"

#include <variant>

namespace carrom::integration {

JournalCheck check_journal(const std::string& json_text) {
    JournalCheck check;
    const auto decoded = proto::decode_journal_text(json_text);
    if (!decoded.ok()) {
        check.problem = "does not decode: " + decoded.error->message;
        return check;
    }
    const proto::MatchJournal& journal = decoded.value;
    check.entries = static_cast<int>(journal.entries.size());
    int last_turn = -1;
    int expected_turn = -1; // the next input's turn: the last one's plus one, plus one more
                            // after a board's end (the next board takes a turn number)
    for (const auto& entry : journal.entries) {
        int input_turn = -1;
        if (const auto* stroke = std::get_if<proto::StrokeEntry>(&entry.event)) {
            input_turn = stroke->turn;
        } else if (const auto* expiry = std::get_if<proto::ClockExpiredEntry>(&entry.event)) {
            input_turn = expiry->turn;
        }
        if (input_turn >= 0) {
            check.turns_consecutive = check.turns_consecutive &&
                                      (expected_turn < 0 || input_turn == expected_turn);
            expected_turn = input_turn + 1;
            if (check.first_turn < 0) {
                check.first_turn = input_turn;
            }
            check.last_turn = input_turn;
        }
        if (const auto* stroke = std::get_if<proto::StrokeEntry>(&entry.event)) {
            ++check.strokes;
            check.turns_in_order = check.turns_in_order && stroke->turn > last_turn;
            last_turn = stroke->turn;
        }
        if (const auto* outcome = proto::outcome_of(entry.event)) {
            check.game_over = outcome->game_end.has_value();
            if (outcome->board_end && !outcome->game_end && expected_turn >= 0) {
                ++expected_turn;
            }
        }
    }
    const proto::ReplayResult replayed = proto::replay(journal);
    if (replayed.error) {
        check.problem = "does not replay: " + replayed.error->message;
    } else if (!replayed.ok()) {
        check.problem = std::to_string(replayed.mismatches) + " mismatches, complete " +
                        std::to_string(replayed.complete);
        for (const auto& step : replayed.steps) {
            for (const auto& d : step.differences) {
                check.problem += "; entry " + std::to_string(step.entry) + ": " + d;
            }
        }
    }
    return check;
}

} // namespace carrom::integration
