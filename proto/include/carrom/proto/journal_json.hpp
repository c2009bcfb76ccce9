#pragma once
// JSON for match journals (journal.hpp); docs/matches.md, "Match journals", describes it:
//   {"format": 1, "match": <created>, "entries": [<entry>, ...]}
// Doubles are written in their shortest round-trip form, so shots and configs decode to the same
// bits and a decoded journal replays exactly. 64-bit hashes are 16 lowercase hex digits (JSON
// numbers are not exact beyond 2^53 in every reader). Decoding untrusted text never throws: it
// returns a value or an Error naming the offending value's path ("entries[4].shot.x"),
// a stable code and one sentence.

#include "carrom/proto/journal.hpp"
#include "carrom/proto/scene_json.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace carrom::proto {

namespace journal_code {
// Besides the scene_code::* codes: "format" is newer than this build reads.
inline constexpr std::string_view kUnsupportedFormat = "unsupported_format";
} // namespace journal_code

inline constexpr std::size_t kMaxJournalBytes = 16 << 20; // 16 MiB of journal text
inline constexpr std::size_t kMaxJournalEntries = 100000;

// "0123456789abcdef": 16 lowercase hex digits.
std::string hash_to_hex(std::uint64_t value);
bool parse_hash_hex(std::string_view text, std::uint64_t& out);

nlohmann::json journal_to_json(const MatchJournal& journal);
nlohmann::json match_created_to_json(const MatchCreated& created);
nlohmann::json journal_entry_to_json(const JournalEntry& entry);
nlohmann::json outcome_record_to_json(const OutcomeRecord& outcome);

Decoded<MatchJournal> decode_journal(const nlohmann::json& j);
// Parses with kMaxJournalBytes and the JSON depth limit, then decode_journal.
Decoded<MatchJournal> decode_journal_text(std::string_view text);
Decoded<MatchCreated> decode_match_created(const nlohmann::json& j,
                                           const std::string& path = "match");
// An entry of a journal whose head is `created` (seats and teams are checked against it).
Decoded<JournalEntry> decode_journal_entry(const nlohmann::json& j, const MatchCreated& created,
                                           const std::string& path);

} // namespace carrom::proto
