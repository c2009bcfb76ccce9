#pragma once
// The JSON text every backend stores (a match's head, each journal entry, a finished match's
// result) and its decoding back, checked: a stored value that does not decode, or a journal that
// misses an entry, throws BadJournal naming the match (a store_bad_journal error).

#include "store/match_store.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace carrom::store::stored {

struct BadJournal : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// --- writing ------------------------------------------------------------------------------------

// matches.head: the journal's head.
std::string head_text(const proto::MatchCreated& created);
// entries.body: one journal entry.
std::string entry_text(const proto::JournalEntry& entry);
// matches.result: {"result": <game result>, "scores": [...]}.
std::string result_text(const rules::GameResult& result, const std::vector<int>& scores);

// --- reading ------------------------------------------------------------------------------------

[[noreturn]] void bad(const MatchId& match, const std::string& what);

proto::MatchCreated decode_head(const MatchId& match, const std::string& text);
// Appends entry number seq (its body text) to journal; seq must be the next number.
void add_entry(const MatchId& match, proto::MatchJournal& journal, std::int64_t seq,
               const std::string& body);
// A match list line from its head; the result (matches.result) when the text is set.
MatchListing listing(const MatchId& match, const std::string& room_code,
                     const std::string& head_text, std::int64_t created_ms,
                     std::optional<std::int64_t> finished_ms,
                     const std::optional<std::string>& result_text);

// An unfinished match for load_unfinished: its journal and seat tokens, read by the backend's
// functions; a BadJournal they throw (or a match without a head) is this match's error only.
RecoveredMatch
recover(const MatchId& match,
        const std::function<std::optional<proto::MatchJournal>()>& read_journal,
        const std::function<std::vector<std::optional<TokenHash>>(int seats)>& read_tokens);

inline constexpr int kMaxListLimit = 100; // recent_matches' limit is clamped to 1..this

} // namespace carrom::store::stored
