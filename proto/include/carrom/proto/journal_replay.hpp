#pragma once
// Writing and replaying match journals (journal.hpp). The server builds each entry from what the
// rules returned (stroke_entry and friends); replay() runs a journal's inputs through the same
// rules and the exact engine and compares every outcome with what the journal recorded. Pure and
// deterministic: a journal replays to the same result on every run and every machine with the
// same physics and rules versions.
//
// Replay follows the server: the game starts from initial_state(created); a stroke is
// rules::play_shot, a clock expiry rules::shot_clock_expired, a forfeit rules::forfeit; after any
// of them, a BoardOver state goes on with rules::start_next_board. Membership entries change no
// state.

#include "carrom/exact_engine.hpp"
#include "carrom/proto/journal.hpp"
#include "carrom/proto/scene_json.hpp"
#include "carrom/rules/match.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace carrom::proto {

namespace replay_code {
// The journal was written by another physics or rules version (see check_versions).
inline constexpr std::string_view kVersionMismatch = "version_mismatch";
// The head cannot start a game (a config the rules refuse, seats that do not match).
inline constexpr std::string_view kBadJournal = "bad_journal";
} // namespace replay_code

// What the journal records of an outcome: `after` is the state the rules returned with it.
OutcomeRecord record_outcome(const rules::ShotOutcome& outcome, const rules::MatchState& after);

// The entries for what the rules returned, built before anything is moved out of the result
// (a stroke's hash covers its events). Preconditions: !result.error.
JournalEntry stroke_entry(std::int64_t time_ms, const rules::PlayResult& result);
JournalEntry clock_expired_entry(std::int64_t time_ms, const rules::PlayResult& result);
JournalEntry forfeit_entry(std::int64_t time_ms, const rules::PlayResult& result,
                           ForfeitReason reason);

// The game's first state: new_match(rule_set, rules, physics), turn_number = first_turn.
rules::MatchState initial_state(const MatchCreated& created);

// An error (code version_mismatch, one sentence naming both versions) when this build's physics
// or rules version differs from the journal's: its strokes would not replay to what it recorded.
std::optional<Error> check_versions(const MatchCreated& created);

// One replayed stroke, clock expiry or forfeit.
struct ReplayStep {
    std::size_t entry = 0;                   // index in journal.entries
    rules::ShotOutcome outcome;              // as replayed (physics only as ReplayOptions asks)
    std::uint64_t result_hash = 0;           // strokes: ResultHash of the replayed simulation
    OutcomeRecord replayed;                  // record_outcome of the replay
    std::optional<rules::RuleError> refused; // the rules refused the input (replay stops here)
    std::vector<std::string> differences;    // empty when the journal's record matches, else
                                             // "<field>: journal <x>, replay <y>" per field
};

struct ReplayOptions {
    bool keep_physics = false;      // keep each outcome's simulation (events, final bodies)
    bool record_trajectory = false; // and its trajectory, to animate it (implies keep_physics)
};

struct ReplayResult {
    // The journal could not be replayed at all (version_mismatch, bad_journal): no steps.
    std::optional<Error> error;
    std::vector<ReplayStep> steps;
    rules::MatchState state; // after the last replayed entry, as the server would hold it
    int mismatches = 0;      // steps with differences (a refused input counts)
    bool complete = false;   // every entry was replayed (no error, no refused input)
    bool ok() const { return !error && mismatches == 0 && complete; }
};

ReplayResult replay(const MatchJournal& journal, const ReplayOptions& options = {});

} // namespace carrom::proto
