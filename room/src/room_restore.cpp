// Room: restoring an unfinished match from its journal (a server restart). The rest of the room
// is in room.cpp and room_game.cpp.
#include "carrom/room/room.hpp"

#include "carrom/proto/journal_replay.hpp"

#include "room_support.hpp"

#include <algorithm>
#include <string>
#include <variant>

namespace carrom::room {

namespace {

struct SeatAfter {
    proto::JournalSeat seat;
    bool dropped = false; // the last membership entry of the seat was a drop
};

std::vector<SeatAfter> seats_after(const proto::MatchJournal& journal) {
    std::vector<SeatAfter> seats;
    for (const auto& seat : journal.created.seats) {
        seats.push_back({seat, false});
    }
    auto at = [&](int seat) -> SeatAfter* {
        if (seat < 0 || static_cast<std::size_t>(seat) >= seats.size()) {
            return nullptr;
        }
        return &seats[static_cast<std::size_t>(seat)];
    };
    for (const auto& entry : journal.entries) {
        if (const auto* joined = std::get_if<proto::SeatJoinedEntry>(&entry.event)) {
            if (SeatAfter* s = at(joined->seat)) {
                *s = {{joined->name, joined->bot}, false};
            }
        } else if (const auto* left = std::get_if<proto::SeatLeftEntry>(&entry.event)) {
            if (SeatAfter* s = at(left->seat)) {
                *s = {};
            }
        } else if (const auto* dropped = std::get_if<proto::SeatDroppedEntry>(&entry.event)) {
            if (SeatAfter* s = at(dropped->seat)) {
                s->dropped = true;
            }
        } else if (const auto* back = std::get_if<proto::SeatReturnedEntry>(&entry.event)) {
            if (SeatAfter* s = at(back->seat)) {
                s->dropped = false;
            }
        }
    }
    return seats;
}

} // namespace

std::vector<proto::JournalSeat> journal_seats(const proto::MatchJournal& journal) {
    std::vector<proto::JournalSeat> out;
    for (const auto& s : seats_after(journal)) {
        out.push_back(s.seat);
    }
    return out;
}

std::optional<std::string> Room::restore(const proto::MatchJournal& journal,
                                         std::vector<RestoredSeat> seats) {
    if (started_ ||
        std::any_of(seats_.begin(), seats_.end(), [](const SeatSlot& s) { return s.occupied; })) {
        return "The room already has a game.";
    }
    const proto::MatchCreated& created = journal.created;
    if (created.rule_set != to_rules(config_.rule_set) || !(created.physics == config_.physics)) {
        return "The room's rule set or physics differ from the journal's.";
    }
    const std::vector<SeatAfter> after = seats_after(journal);
    if (after.size() != seats_.size() || seats.size() != seats_.size()) {
        return "The journal has " + std::to_string(after.size()) + " seats; a room has " +
               std::to_string(seats_.size()) + ".";
    }
    for (std::size_t i = 0; i < after.size(); ++i) {
        if (after[i].seat.name.empty()) {
            return "Seat " + std::to_string(i) + " was left; the match cannot go on.";
        }
        if (after[i].seat.bot != (seats[i].bot != nullptr)) {
            return "Seat " + std::to_string(i) +
                   (after[i].seat.bot ? " is a bot's" : " is not a bot's") + " in the journal.";
        }
    }
    proto::ReplayResult replayed = proto::replay(journal);
    if (replayed.error) {
        return replayed.error->message;
    }
    if (!replayed.ok()) {
        return "The journal does not replay clean (" + std::to_string(replayed.mismatches) +
               " outcomes differ, " +
               (replayed.complete ? std::string("every entry replayed")
                                  : std::string("an input refused")) +
               ").";
    }
    if (replayed.state.phase == rules::Phase::GameOver) {
        return "The match is over.";
    }

    config_.rules = created.rules;
    match_ = std::move(replayed.state);
    match_id_ = created.match_id;
    journal_seq_ = static_cast<std::int64_t>(journal.entries.size());
    started_ = true;
    counters_.matches.fetch_add(1, std::memory_order_relaxed);
    const std::int64_t now = clock_.now_ms();
    for (std::size_t i = 0; i < seats_.size(); ++i) {
        SeatSlot& slot = seats_[i];
        slot.occupied = true;
        slot.name = after[i].seat.name;
        if (seats[i].bot) {
            slot.bot = std::move(seats[i].bot);
            continue;
        }
        slot.player_id = seats[i].player_id;
        slot.grace_deadline_ms = now + seconds_to_ms(config_.grace_s);
        // The seat holder's token stays as the sink has it (no seat_holder call): a player who
        // has not resumed yet can still do so after another restart.
        if (!after[i].dropped) {
            journal_event(proto::SeatDroppedEntry{static_cast<int>(i)});
        }
    }
    bot_turn_taken_ = -1;
    start_turn();
    return std::nullopt;
}

} // namespace carrom::room
