// The carrom-server executable as scripts see it: stdout holds only the "listening on" line,
// logs go to stderr (docs/server.md).
#include "support/command_run.hpp"
#include "support/read_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <string>

namespace carrom::server {
namespace {

using test_support::CommandRun;
using test_support::read_file;
using test_support::run_command;

// "listening on 127.0.0.1:PORT\n" and nothing else. (No std::regex: g++ 12 warns in its
// std::function at -O1 with the sanitizers, and warnings are errors.)
bool is_listening_line(const std::string& out) {
    const std::string prefix = "listening on 127.0.0.1:";
    if (out.size() < prefix.size() + 2 || out.compare(0, prefix.size(), prefix) != 0 ||
        out.back() != '\n') {
        return false;
    }
    const std::string port = out.substr(prefix.size(), out.size() - prefix.size() - 1);
    return port.find_first_not_of("0123456789") == std::string::npos;
}

TEST(ServerCli, StdoutHoldsOnlyTheListeningLineAndLogsGoToStderr) {
    const std::string err_path =
        ::testing::TempDir() + "carrom_server_cli_" + std::to_string(getpid()) + ".err";
    // info level logs at start, on the signal and at the end; timeout sends SIGTERM after 1 s.
    const CommandRun ran =
        run_command(std::string("timeout -s TERM 1 ") + CARROM_SERVER_PATH +
                    " --host 127.0.0.1 --port 0 --data none --log-level info 2> " + err_path);
    EXPECT_EQ(ran.exit, 124) << ran.out; // stopped by timeout's SIGTERM
    EXPECT_TRUE(is_listening_line(ran.out)) << ran.out;
    const std::string err = read_file(err_path);
    EXPECT_NE(err.find("carrom-server on 127.0.0.1:"), std::string::npos) << err;
    EXPECT_NE(err.find("stopped"), std::string::npos) << err;
    std::remove(err_path.c_str());
}

} // namespace
} // namespace carrom::server
