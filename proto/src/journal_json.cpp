// Encoding of match journals (see journal_json.hpp).

#include "carrom/proto/journal_json.hpp"

#include "carrom/proto/match_json.hpp"

#include <array>
#include <type_traits>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;

Json seats_to_json(const std::vector<JournalSeat>& seats) {
    Json out = Json::array();
    for (const JournalSeat& seat : seats) {
        out.push_back({{"name", seat.name}, {"bot", seat.bot}});
    }
    return out;
}

Json fouls_to_json(const std::vector<rules::RuleCode>& fouls) {
    Json out = Json::array();
    for (rules::RuleCode code : fouls) {
        out.push_back(std::string(rules::to_string(code)));
    }
    return out;
}

// The event's own fields (the caller adds "type" and "time_ms").
void add_event(Json& out, const JournalEvent& event) {
    std::visit(
        [&out](const auto& e) {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, StrokeEntry>) {
                out["turn"] = e.turn;
                out["seat"] = e.seat;
                out["shot"] = rules_shot_to_json(e.shot);
                out["result_hash"] = hash_to_hex(e.result_hash);
                out["outcome"] = outcome_record_to_json(e.outcome);
            } else if constexpr (std::is_same_v<T, ClockExpiredEntry>) {
                out["turn"] = e.turn;
                out["seat"] = e.seat;
                out["outcome"] = outcome_record_to_json(e.outcome);
            } else if constexpr (std::is_same_v<T, ForfeitEntry>) {
                out["turn"] = e.turn;
                out["seat"] = e.seat;
                out["reason"] = std::string(to_string(e.reason));
                out["outcome"] = outcome_record_to_json(e.outcome);
            } else if constexpr (std::is_same_v<T, SeatJoinedEntry>) {
                out["seat"] = e.seat;
                out["name"] = e.name;
                out["bot"] = e.bot;
            } else if constexpr (std::is_same_v<T, RematchEntry>) {
                out["next_match"] = e.next_match_id;
            } else {
                out["seat"] = e.seat; // leave, drop, return
            }
        },
        event);
}

} // namespace

std::string hash_to_hex(std::uint64_t value) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out(16, '0');
    for (std::size_t i = 0; i < 16; ++i) {
        out[15 - i] = kHex[value & 0xfU];
        value >>= 4U;
    }
    return out;
}

bool parse_hash_hex(std::string_view text, std::uint64_t& out) {
    if (text.size() != 16) {
        return false;
    }
    std::uint64_t value = 0;
    for (char c : text) {
        std::uint64_t digit = 0;
        if (c >= '0' && c <= '9') {
            digit = static_cast<std::uint64_t>(c - '0');
        } else if (c >= 'a' && c <= 'f') {
            digit = static_cast<std::uint64_t>(c - 'a' + 10);
        } else {
            return false;
        }
        value = (value << 4U) | digit;
    }
    out = value;
    return true;
}

Json outcome_record_to_json(const OutcomeRecord& outcome) {
    Json out = {{"state_hash", hash_to_hex(outcome.state_hash)},
                {"pocketed", outcome.pocketed},
                {"fouls", fouls_to_json(outcome.fouls)},
                {"scores", outcome.scores},
                {"next_seat", outcome.next_seat}};
    if (outcome.board_end) {
        out["board_end"] = board_result_to_json(*outcome.board_end);
    }
    if (outcome.game_end) {
        out["game_end"] = game_result_to_json(*outcome.game_end);
    }
    return out;
}

Json match_created_to_json(const MatchCreated& c) {
    return {{"match_id", c.match_id},
            {"rematch_of", c.rematch_of.empty() ? Json(nullptr) : Json(c.rematch_of)},
            {"room", c.room_code},
            {"rule_set", std::string(rules::to_string(c.rule_set))},
            {"rules", rules_config_to_json(c.rules)},
            {"physics", config_to_json(c.physics)},
            {"seats", seats_to_json(c.seats)},
            {"first_turn", c.first_turn},
            {"versions",
             {{"server", c.versions.server},
              {"physics", c.versions.physics},
              {"rules", c.versions.rules}}},
            {"time_ms", c.time_ms}};
}

Json journal_entry_to_json(const JournalEntry& entry) {
    Json out = {{"type", std::string(event_type(entry.event))}, {"time_ms", entry.time_ms}};
    add_event(out, entry.event);
    return out;
}

Json journal_to_json(const MatchJournal& journal) {
    Json entries = Json::array();
    for (const JournalEntry& entry : journal.entries) {
        entries.push_back(journal_entry_to_json(entry));
    }
    return {{"format", kJournalFormat},
            {"match", match_created_to_json(journal.created)},
            {"entries", std::move(entries)}};
}

} // namespace carrom::proto
