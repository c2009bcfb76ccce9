#pragma once
// The version of the exact engine's results. A match journal records it (with the rules
// version) so that a journal written by a build whose physics differs is recognised instead of
// being replayed to different outcomes (docs/store.md).
//
// Bump it whenever any input can give a different result than before, bit for bit: a changed
// event time, position, velocity or pocket order. tests/common/exact_pinned_results_test.cpp
// pins results: a change that alters its constants needs a bump here.

namespace carrom {

inline constexpr int kPhysicsVersion = 2;

} // namespace carrom
