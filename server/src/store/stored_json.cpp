#include "store/stored_json.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/match_json.hpp"

#include <algorithm>

namespace carrom::store::stored {
namespace {

using Json = nlohmann::json;

// Text for a column. Names are valid UTF-8 when they come from the wire (the JSON parser checks);
// anything else is replaced rather than failing every retry.
std::string dump(const Json& j) {
    return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

Json parse_stored(const MatchId& match, const std::string& text, std::string_view what) {
    auto parsed = proto::parse_json_text(text, proto::kMaxJournalBytes);
    if (!parsed.ok()) {
        bad(match, std::string(what) + ": " + parsed.error->message);
    }
    return std::move(parsed.value);
}

} // namespace

std::string head_text(const proto::MatchCreated& created) {
    return dump(proto::match_created_to_json(created));
}

std::string entry_text(const proto::JournalEntry& entry) {
    return dump(proto::journal_entry_to_json(entry));
}

std::string result_text(const rules::GameResult& result, const std::vector<int>& scores) {
    return dump(Json{{"result", proto::game_result_to_json(result)}, {"scores", scores}});
}

void bad(const MatchId& match, const std::string& what) {
    throw BadJournal("the stored journal of match " + match + " is damaged: " + what);
}

proto::MatchCreated decode_head(const MatchId& match, const std::string& text) {
    auto head = proto::decode_match_created(parse_stored(match, text, "match"));
    if (!head.ok()) {
        bad(match, head.error->path + ": " + head.error->message);
    }
    return std::move(head.value);
}

void add_entry(const MatchId& match, proto::MatchJournal& journal, std::int64_t seq,
               const std::string& body) {
    const auto expected = static_cast<std::int64_t>(journal.entries.size());
    if (seq != expected) {
        bad(match, "entry " + std::to_string(expected) + " is missing");
    }
    const std::string at = "entries[" + std::to_string(seq) + "]";
    auto entry = proto::decode_journal_entry(parse_stored(match, body, at), journal.created, at);
    if (!entry.ok()) {
        bad(match, entry.error->path + ": " + entry.error->message);
    }
    journal.entries.push_back(std::move(entry.value));
}

MatchListing listing(const MatchId& match, const std::string& room_code,
                     const std::string& head_text, std::int64_t created_ms,
                     std::optional<std::int64_t> finished_ms,
                     const std::optional<std::string>& result_text) {
    MatchListing m;
    m.id = match;
    m.room_code = room_code;
    const proto::MatchCreated head = decode_head(m.id, head_text);
    m.rule_set = head.rule_set;
    for (const proto::JournalSeat& seat : head.seats) {
        m.teams.push_back(
            rules::team_of_seat(static_cast<int>(m.players.size()), head.rules.seat_count));
        m.players.push_back(seat.name);
    }
    m.created_ms = created_ms;
    m.finished_ms = finished_ms;
    if (result_text) {
        const Json r = parse_stored(m.id, *result_text, "result");
        const int teams = rules::team_count(head.rules.seat_count);
        if (!r.is_object() || !r.contains("result") || !r.contains("scores")) {
            bad(m.id, "its stored result does not decode");
        }
        auto result = proto::decode_game_result(r["result"], teams, "result");
        const Json& scores = r["scores"];
        if (!result.ok() || !scores.is_array() ||
            scores.size() != static_cast<std::size_t>(teams) ||
            !std::all_of(scores.begin(), scores.end(),
                         [](const Json& s) { return s.is_number_integer(); })) {
            bad(m.id, "its stored result does not decode");
        }
        m.result = result.value;
        for (const Json& s : scores) {
            m.scores.push_back(s.get<int>());
        }
    }
    return m;
}

RecoveredMatch
recover(const MatchId& match,
        const std::function<std::optional<proto::MatchJournal>()>& read_journal,
        const std::function<std::vector<std::optional<TokenHash>>(int seats)>& read_tokens) {
    RecoveredMatch out;
    out.id = match;
    try {
        out.journal = read_journal();
        if (!out.journal) {
            bad(match, "it has no head");
        }
        out.seat_tokens = read_tokens(out.journal->created.rules.seat_count);
    } catch (const BadJournal& e) { // this match only; the others recover
        out.journal.reset();
        out.error = StoreError{std::string(store_code::kBadJournal), e.what()};
    }
    return out;
}

} // namespace carrom::store::stored
