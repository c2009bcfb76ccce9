#pragma once
// A match journal: everything needed to rebuild one game bit for bit. The physics and the rules
// are exact and deterministic, so a game is fully described by its configs, its seats and the
// inputs that changed its state (strokes, shot clock expiries, forfeits); each of those records
// what it did (OutcomeRecord), so that a replay (journal_replay.hpp) can verify every step.
// Membership changes (joins, leaves, drops, returns) are recorded too; they change no state.
//
// One journal holds one game. A rematch starts a new journal (its MatchCreated names the previous
// one in rematch_of) and closes the old one with a RematchEntry naming the new one. Plain data;
// the JSON form is in journal_json.hpp and docs/matches.md, "Match journals".

#include "carrom/config.hpp"
#include "carrom/enum_names.hpp"
#include "carrom/physics_version.hpp"
#include "carrom/rules/match_state.hpp"
#include "carrom/rules/rule_code.hpp"
#include "carrom/rules/rule_set.hpp"
#include "carrom/rules/rules_config.hpp"
#include "carrom/rules/rules_version.hpp"
#include "carrom/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::proto {

// The version of the journal's JSON form. Bump it on any change an older reader would misread.
inline constexpr int kJournalFormat = 1;

inline constexpr std::size_t kMaxMatchIdBytes = 64;
// 1..kMaxMatchIdBytes characters of [0-9A-Za-z_-] (safe in a URL path and a file name).
bool is_match_id(std::string_view text);

struct JournalSeat {
    std::string name; // as the room showed it (a player name, or "Bot (medium)")
    bool bot = false; // a server-side bot
    friend bool operator==(const JournalSeat&, const JournalSeat&) = default;
};

// The versions of the software that wrote the journal. A replay by another physics or rules
// version is refused (check_versions in journal_replay.hpp); the server version is information.
struct JournalVersions {
    std::string server; // e.g. "0.1.0"
    int physics = kPhysicsVersion;
    int rules = rules::kRulesVersion;
    friend bool operator==(const JournalVersions&, const JournalVersions&) = default;
};

// The head of a journal, written when the game starts (every seat taken). The game's first state
// is new_match(rule_set, rules, physics) with turn_number = first_turn.
struct MatchCreated {
    std::string match_id;   // unique in the store, chosen by the server (is_match_id)
    std::string rematch_of; // the previous game's match_id in the same room; empty if none
    std::string room_code;  //
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    rules::RulesConfig rules{}; // every rule: the room's options, and first_breaker (who breaks)
    PhysicsConfig physics{};    //
    std::vector<JournalSeat> seats; // by seat index, as the game starts
    int first_turn = 0;             // turn number of the game's first turn (rematches go on
                                    // counting from the previous game)
    JournalVersions versions;
    std::int64_t time_ms = 0; // server wall clock, Unix time in ms
    friend bool operator==(const MatchCreated&, const MatchCreated&) = default;
};

// What an outcome did, as the journal records it for verification. state_hash pins the whole
// state the rules returned; the other fields make the journal readable and a mismatch explicable.
struct OutcomeRecord {
    std::uint64_t state_hash = 0;       // rules::hash_match_state of the state after the outcome
                                        // (before start_next_board)
    std::vector<int> pocketed;          // piece ids pocketed by the stroke, in order
    std::vector<rules::RuleCode> fouls; //
    std::vector<int> scores;            // per team, after the outcome
    int next_seat = 0;                  // whose turn is next
    std::optional<rules::BoardResult> board_end;
    std::optional<rules::GameResult> game_end;
    friend bool operator==(const OutcomeRecord&, const OutcomeRecord&) = default;
};

// An accepted stroke.
struct StrokeEntry {
    int turn = 0;                  // the state's turn_number when it was played
    int seat = 0;                  //
    Shot shot{};                   // exactly as played
    std::uint64_t result_hash = 0; // ResultHash of the stroke's simulation (result_hash.hpp)
    OutcomeRecord outcome;
    friend bool operator==(const StrokeEntry&, const StrokeEntry&) = default;
};

// The seat to move ran out of time.
struct ClockExpiredEntry {
    int turn = 0;
    int seat = 0;
    OutcomeRecord outcome;
    friend bool operator==(const ClockExpiredEntry&, const ClockExpiredEntry&) = default;
};

enum class ForfeitReason : std::uint8_t {
    Left,         // "left": the player left the room during the game
    GraceExpired, // "grace_expired": the player's connection dropped and did not come back
};
inline constexpr enum_names::Table<ForfeitReason, 2> kForfeitReasonNames{
    {{ForfeitReason::Left, "left"}, {ForfeitReason::GraceExpired, "grace_expired"}}};
std::string_view to_string(ForfeitReason reason);
bool parse(std::string_view text, ForfeitReason& out);

// A seat gave up the game (its team loses).
struct ForfeitEntry {
    int turn = 0; // the state's turn_number at the time (any seat's turn)
    int seat = 0;
    ForfeitReason reason = ForfeitReason::Left;
    OutcomeRecord outcome;
    friend bool operator==(const ForfeitEntry&, const ForfeitEntry&) = default;
};

struct SeatJoinedEntry { // a seat freed during the journal was taken again
    int seat = 0;
    std::string name;
    bool bot = false;
    friend bool operator==(const SeatJoinedEntry&, const SeatJoinedEntry&) = default;
};
struct SeatLeftEntry { // the seat's holder left for good (a running game was forfeited first)
    int seat = 0;
    friend bool operator==(const SeatLeftEntry&, const SeatLeftEntry&) = default;
};
struct SeatDroppedEntry { // the holder's connection dropped; the seat is kept for the grace period
    int seat = 0;
    friend bool operator==(const SeatDroppedEntry&, const SeatDroppedEntry&) = default;
};
struct SeatReturnedEntry { // the holder resumed the seat
    int seat = 0;
    friend bool operator==(const SeatReturnedEntry&, const SeatReturnedEntry&) = default;
};
// Every seat asked for a rematch: the next game is journaled under next_match_id. Last entry.
struct RematchEntry {
    std::string next_match_id;
    friend bool operator==(const RematchEntry&, const RematchEntry&) = default;
};

using JournalEvent = std::variant<StrokeEntry, ClockExpiredEntry, ForfeitEntry, SeatJoinedEntry,
                                  SeatLeftEntry, SeatDroppedEntry, SeatReturnedEntry, RematchEntry>;

// The JSON "type" of each event: "stroke", "clock_expired", "forfeit", "join", "leave", "drop",
// "return", "rematch".
std::string_view event_type(const JournalEvent& event);

struct JournalEntry {
    std::int64_t time_ms = 0; // server wall clock, Unix time in ms
    JournalEvent event;
    friend bool operator==(const JournalEntry&, const JournalEntry&) = default;
};

struct MatchJournal {
    MatchCreated created;
    std::vector<JournalEntry> entries; // in the order they happened
    friend bool operator==(const MatchJournal&, const MatchJournal&) = default;
};

// The outcome record of an entry, or null for membership entries.
const OutcomeRecord* outcome_of(const JournalEvent& event);

} // namespace carrom::proto
