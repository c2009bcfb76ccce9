// carrom-client on a machine without a sound card (CI, or scripts/play.sh on a headless machine
// under xvfb-run): the offline demo plays its sounds for a few seconds (the break and the shots
// it plays for us), and stderr must hold at most one line about audio, the client's own
// sentence; OpenAL, ALSA and SFML used to print hundreds. On a machine with a sound card the
// client prints nothing about audio, which passes too.

#ifdef CARROM_CLIENT_PATH

#include "client_program.hpp"
#include "support/child_process.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

TEST(NoAudioDevice, TheClientSaysSoInOneLineAndPlaysOn) {
    const std::vector<std::string> argv = client_argv(
        {"--demo", "--demo-break-at", "0.2", "--demo-autoplay", "0.3", "--timeout", "4"});
    ChildProcess client(argv, {client_asan_options()});
    ASSERT_TRUE(client.started());
    const auto exit = client.wait_exit(Clock::now() + 60s);
    client.wait_line(ChildProcess::Stream::Err, "\n", Clock::now() + 500ms); // the rest of it
    std::string all;
    std::vector<std::string> lines;
    for (const std::string& line : client.lines(ChildProcess::Stream::Err)) {
        all += line + "\n";
        // --timeout ends the run on purpose and says so; SFML says once that Xvfb's GL cannot
        // wait for vertical sync.
        if (line.rfind("carrom-client: gave up after", 0) != 0 &&
            line != "Setting vertical sync not supported") {
            lines.push_back(line);
        }
    }
    EXPECT_EQ(exit, 3) << all; // ran until --timeout
    ASSERT_LE(lines.size(), 1u) << all;
    if (!lines.empty()) {
        EXPECT_EQ(lines[0], "carrom-client: no audio device: sounds are off") << all;
    }
}

} // namespace
} // namespace carrom::client

#endif
