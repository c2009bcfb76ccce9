#pragma once
// `carrom-sim --replay`: reads a match journal (docs/matches.md, "Match journals") from `in`,
// replays it through the rules and the exact engine, and writes each replayed stroke's outcome
// to `out` (docs/carrom-sim.md). Returns the exit code: 0 when every outcome matches what the
// journal recorded, 1 when one differs (or the rules refuse an input), 2 when the journal is
// unreadable or invalid, or was written by another physics or rules version ({"error": ...} on
// `err`).

#include <iosfwd>

namespace carrom {
int run_replay_mode(std::istream& in, std::ostream& out, std::ostream& err, bool pretty);
} // namespace carrom
