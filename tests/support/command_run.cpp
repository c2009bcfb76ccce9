#include "support/command_run.hpp"

#include <sys/wait.h>

#include <cstdio>

namespace carrom::test_support {

CommandRun run_command(const std::string& command) {
    CommandRun ran;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) {
        return ran;
    }
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) {
        ran.out.append(buffer, n);
    }
    const int status = pclose(pipe);
    ran.exit = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return ran;
}

} // namespace carrom::test_support
