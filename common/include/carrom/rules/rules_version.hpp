#pragma once
// The version of the rules' results. A match journal records it (with the physics version) so
// that a journal written by a build whose rules differ is recognised instead of being replayed
// to different outcomes (docs/store.md).
//
// Bump it whenever a match state plus a stroke can give another state or outcome than before:
// a changed rule, default, scoring or return spot, or a change to hash_match_state
// (state_hash.hpp), whose values journals store. tests/common/state_hash_test.cpp pins the hash
// of a new match.

namespace carrom::rules {

inline constexpr int kRulesVersion = 1;

} // namespace carrom::rules
