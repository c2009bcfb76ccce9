#pragma once
// carrom-golden record: a real match as one of its players receives it. A bot of this process
// (bots::BotRunner) creates a room on a running carrom-server with the server's bots in every
// other seat, plays one game, and every message it receives is kept with its arrival time. The text
// kept is the decoded message encoded again with proto::encode, the server's own encoder, so it is
// the server's text in the server's field order.

#include "carrom/golden/golden_json.hpp"

#include <string>
#include <variant>
#include <vector>

namespace carrom::golden {

struct RecordOptions {
    std::string url = "ws://127.0.0.1:7777";
    int seats = 2;  // 2 (singles) or 4 (doubles)
    int boards = 1; // boards of the match
    double timeout_s = 600.0;
    std::uint64_t seed = 1;     // the recording bot's random choices
    std::string level = "hard"; // the server's bots: easy, medium or hard
    // The recording bot's: "fouls" (a soft break, then the striker into the nearest pocket, again
    // and again: every second shot a foul, which costs a due while the team has no coin to give
    // back), "random" or "greedy".
    std::string strategy = "fouls";
};

// The stream, or why it could not be recorded.
std::variant<std::vector<StreamLine>, std::string> record_stream(const RecordOptions& options);

} // namespace carrom::golden
