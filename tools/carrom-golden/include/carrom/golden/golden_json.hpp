#pragma once
// What every golden case file shares: reading and writing its JSON, the recorded server stream
// (one line per message a client received, with its arrival time), and numbers rounded to the
// precision the files keep.

#include "carrom/body.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace carrom::golden {

// One message as a client received it: the raw text frame and its arrival, s since the first.
struct StreamLine {
    double at_s = 0.0;
    std::string text;
};

// A stream file: one JSON object per line, {"at": s, "line": "<server message text>"}.
std::vector<StreamLine> parse_stream(const std::string& jsonl);
std::string format_stream(const std::vector<StreamLine>& stream);

// x rounded to 1e-6 (board px, s): the files keep six decimals, the replays compare within
// kTolerance.
double rounded(double x);
inline constexpr double kTolerance = 2e-6;

// A body kind by its wire name (black for an unknown one).
BodyKind kind_named(const std::string& name);

// The text of a file, or nothing when it cannot be read.
std::optional<std::string> read_text(const std::string& path);
// Writes text; false when it cannot.
bool write_text(const std::string& path, const std::string& text);
// A case file's text: two-space indented JSON with a final newline.
std::string format_case(const nlohmann::json& value);

// The first difference between a replay's result and the expected one: numbers within
// kTolerance, everything else equal. Empty when they agree; else the JSON path and both values.
std::string first_difference(const nlohmann::json& expected, const nlohmann::json& actual,
                             const std::string& path = "$");

} // namespace carrom::golden
