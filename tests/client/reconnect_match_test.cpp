// carrom-client through a network cut: carrom-server, tests/support/fault_proxy.py in front of
// it, a carrom-bot creating the room through the proxy and carrom-client (--autoplay easy,
// --final-state) joining through it. A second into the match the proxy cuts every
// connection and refuses new ones for 3 s: the client resumes its seat by itself, plays the game
// to the end and writes the final state with the bot's scores.
#include "client_program.hpp"
#include "support/child_process.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace carrom::client {
namespace {

using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

std::string after(const std::optional<std::string>& line, const std::string& prefix) {
    return line ? line->substr(prefix.size()) : std::string();
}

TEST(ReconnectMatch, ClientResumesThroughACutAndFinishesTheGame) {
    const auto dir = std::filesystem::path(::testing::TempDir()) /
                     ("carrom_reconnect_match_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string prefix = "listening on 127.0.0.1:";
    ChildProcess server({CARROM_SERVER_PATH, "--host", "127.0.0.1", "--port", "0", "--shot-clock",
                         "0", "--time-scale", "25", "--idle-timeout", "2", "--grace", "20",
                         "--log-level", "warn", "--data", "none"});
    const std::string server_port =
        after(server.wait_line(ChildProcess::Stream::Out, prefix, Clock::now() + 15s), prefix);
    ASSERT_FALSE(server_port.empty());
    const char* source = std::getenv("CARROM_SOURCE_DIR");
    const std::string control = (dir / "control").string();
    ChildProcess proxy(
        {"python3", std::string(source != nullptr ? source : ".") + "/tests/support/fault_proxy.py",
         "--target", "127.0.0.1:" + server_port, "--control", control});
    const std::string port =
        after(proxy.wait_line(ChildProcess::Stream::Out, prefix, Clock::now() + 15s), prefix);
    ASSERT_FALSE(port.empty()) << proxy.output();
    const std::string url = "ws://127.0.0.1:" + port;
    ChildProcess bot({CARROM_BOT_PATH,
                      "--url",
                      url,
                      "--name",
                      "Bot",
                      "--create",
                      "--rule-set",
                      "freestyle",
                      "--target-points",
                      "150",
                      "--shot-clock",
                      "0",
                      "--strategy",
                      "random",
                      "--seed",
                      "3",
                      "--timeout",
                      "120",
                      "--resume-for",
                      "25"});
    const std::string code =
        after(bot.wait_line(ChildProcess::Stream::Err, "room ", Clock::now() + 15s), "room ");
    ASSERT_EQ(code.size(), 6u) << bot.output();
    const std::string final_state = (dir / "final.json").string();
    const std::vector<std::string> argv =
        client_argv({std::string("--url"), url, std::string("--name"), std::string("Ana"),
                     std::string("--join"), code, std::string("--mute"), std::string("--width"),
                     std::string("700"), std::string("--height"), std::string("700"),
                     std::string("--autoplay"), std::string("easy"), std::string("--final-state"),
                     final_state, std::string("--timeout"), std::string("110")});
    ChildProcess client(argv, {client_asan_options()});
    ASSERT_TRUE(client.wait_line(ChildProcess::Stream::Out, "room ", Clock::now() + 30s))
        << client.output();
    std::this_thread::sleep_for(1s); // the match is under way
    {
        std::ofstream out(control + ".tmp");
        out << "cut 3\n";
    }
    std::filesystem::rename(control + ".tmp", control);
    const auto cut = proxy.wait_line(ChildProcess::Stream::Out, "cut ", Clock::now() + 5s);
    ASSERT_TRUE(cut);
    // The client's and the bot's WebSockets, and a read of the client's HTTP API (ratings) if
    // one was open at that moment.
    EXPECT_TRUE(*cut == "cut 2 connections for 3.0 s" || *cut == "cut 3 connections for 3.0 s")
        << *cut;
    const auto exit = client.wait_exit(Clock::now() + 120s);
    ASSERT_TRUE(exit) << client.output();
    EXPECT_EQ(*exit, 0) << client.output();
    const auto summary_line = bot.wait_line(ChildProcess::Stream::Out, "{", Clock::now() + 20s);
    ASSERT_TRUE(summary_line) << bot.output() << "\nThe client said:\n" << client.output();
    const auto summary = nlohmann::json::parse(*summary_line, nullptr, false);
    EXPECT_EQ(summary["ok"], true) << *summary_line;
    EXPECT_GE(summary["resumes"].get<int>(), 1);
    std::ifstream in(final_state);
    ASSERT_TRUE(in) << "no final state; the client said:\n" << client.output();
    const auto state = nlohmann::json::parse(in, nullptr, false);
    EXPECT_EQ(state["room"], code);
    EXPECT_EQ(state["you"], 1);
    EXPECT_EQ(state["scores"], summary["scores"]);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace carrom::client
