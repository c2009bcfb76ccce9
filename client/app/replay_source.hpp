#pragma once
// Where carrom-client --replay gets its journal: an http:// URL (a server's GET /matches/ID),
// a file, or "-" for standard input; then the journal is decoded and replayed (ReplayModel).

#include "carrom/client/replay_model.hpp"

#include <string>
#include <variant>

namespace carrom::client::app {

// The replay, or one line saying why not (the journal's error path, sentence and code, or what
// went wrong reading the file or fetching the URL).
std::variant<ReplayModel, std::string> load_replay(const std::string& source);

} // namespace carrom::client::app
