#pragma once
// `carrom-sim --frame-error FRAMES JOURNAL`: what a client drew against the exact trajectory.
// Replays the match journal (docs/matches.md, "Match journals") with the exact engine and reads
// the client's frame log (carrom-client --frame-log, docs/client.md); for each stroke it prints
// the error of the drawn positions at the frames' shot times (RMS, max), the frames that jumped
// or froze, and whether the board drawn at rest after the stroke is the server's final board
// (docs/carrom-sim.md, "Measuring a client's frames"). Exit code 0, or 2 ({"error": ...} on
// `err`) when the journal or the frame log is unreadable or invalid.

#include <iosfwd>
#include <string>

namespace carrom {
int run_frame_error_mode(const std::string& frames_path, const std::string& journal_path,
                         std::ostream& out, std::ostream& err, bool pretty);
} // namespace carrom
