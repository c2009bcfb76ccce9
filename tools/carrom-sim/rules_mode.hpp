#pragma once
// `carrom-sim --rules`: reads a rules scenario from `in`, writes the result to `out`, errors to
// `err`; returns the process exit code.

#include <iosfwd>

namespace carrom {
int run_rules_mode(std::istream& in, std::ostream& out, std::ostream& err);
} // namespace carrom
