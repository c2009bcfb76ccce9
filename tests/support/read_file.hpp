#pragma once
// A file's whole contents, for the tests that check what a program wrote (its stderr sent to a
// file, a page it serves).

#include <string>

namespace carrom::test_support {

// The file's bytes; empty if it cannot be read.
std::string read_file(const std::string& path);

} // namespace carrom::test_support
