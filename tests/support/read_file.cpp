#include "support/read_file.hpp"

#include <fstream>
#include <sstream>

namespace carrom::test_support {

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

} // namespace carrom::test_support
