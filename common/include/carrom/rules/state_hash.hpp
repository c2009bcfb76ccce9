#pragma once
// A 64-bit FNV-1a hash over every field of a match state (both configs included). Two states
// with the same hash are equal (barring a collision), so a match journal stores the hash of the
// state after each stroke and a replay compares it (proto/journal_replay.hpp). Doubles are
// hashed by their bits: -0.0 and 0.0 differ. The value is part of the journal format: changing
// what is hashed, or how, needs a kRulesVersion bump (rules_version.hpp).

#include "carrom/rules/match_state.hpp"

#include <cstdint>

namespace carrom::rules {

std::uint64_t hash_match_state(const MatchState& state);

} // namespace carrom::rules
