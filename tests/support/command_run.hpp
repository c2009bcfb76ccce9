#pragma once
// A command line run through the shell, for the tests that run built programs (carrom-server,
// carrom-bot, carrom-load, carrom-sim): its standard output and its exit status.

#include <string>

namespace carrom::test_support {

// exit is -1 when the command did not exit normally or could not be started.
struct CommandRun {
    int exit = -1;
    std::string out;
};

// Runs `command` with /bin/sh and waits for it; its standard error goes where this process's
// does unless the command redirects it.
CommandRun run_command(const std::string& command);

} // namespace carrom::test_support
