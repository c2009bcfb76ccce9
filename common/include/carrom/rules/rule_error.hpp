#pragma once
// Why the rules refused something (a shot, a placement, a config). Plain data.

#include <string>

namespace carrom::rules {

struct RuleError {
    std::string code;    // stable machine-readable code, e.g. "striker_overlaps"
    std::string field;   // the offending field ("shot.x", "seat", ...), empty if none
    std::string message; // one plain sentence
};

} // namespace carrom::rules
