#pragma once
// Shared pieces of the integration tests: the real server in this process on 127.0.0.1 with an
// ephemeral port, bot matches driven over real WebSocket connections, and a hand-driven client
// for sending exactly the frames a test wants.

#include "carrom/bots/bot_runner.hpp"
#include "carrom/bots/strategy.hpp"
#include "carrom/net/connection.hpp"
#include "carrom/server/server.hpp"

#include "support/command_run.hpp"

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace carrom::integration {

// Shot playback speed-up for tests (ServerSettings::time_scale): a whole match takes seconds.
inline constexpr double kTestTimeScale = 25.0;

// Settings for tests: 127.0.0.1, ephemeral port, 2 I/O threads, no shot clock, fast playback.
server::ServerSettings test_settings();

// The named strategy (bots::make_strategy with its default level) seeded with seed; the name
// must be one make_strategy knows.
std::unique_ptr<bots::Strategy> test_strategy(const std::string& name, std::uint64_t seed);

// A command line run through the shell: its standard output and exit status (tests/support/).
using test_support::CommandRun;
using test_support::run_command;

class TestServer {
public:
    explicit TestServer(server::ServerSettings settings = test_settings());
    ~TestServer();
    std::string url() const { return "ws://127.0.0.1:" + std::to_string(port_); }
    server::Server& server() { return *server_; }

private:
    std::unique_ptr<server::Server> server_;
    std::uint16_t port_ = 0;
};

struct MatchSpec {
    proto::CreateRoom create;          // the room the first bot creates
    std::string strategy = "sampling"; // both bots
    std::uint64_t seed = 1;
    int games = 1;
    bool spectator = false; // a third bot watches
    std::chrono::milliseconds timeout{60000};
};

struct MatchRun {
    bots::BotSummary creator;
    bots::BotSummary joiner;
    std::optional<bots::BotSummary> spectator;
    std::string code;
};

// Plays one match between two bots (plus a spectator if asked) to the end.
MatchRun play_match(const std::string& url, const MatchSpec& spec);

// Plays `count` matches at once, each bot on its own thread.
std::vector<MatchRun> play_matches(const std::string& url, const std::vector<MatchSpec>& specs);

// A client the test drives message by message.
class ManualClient {
public:
    explicit ManualClient(const std::string& url, const std::string& name = "tester");
    // hello and the welcome; returns the welcome.
    proto::Welcome hello(std::optional<std::string> token = std::nullopt);
    void send(const proto::ClientMessage& message) { connection_->send(message); }
    void send_text(const std::string& text) { connection_->send_text(text); }
    // The next message satisfying `match` (others are kept in history()); nothing on timeout.
    template <class T>
    std::optional<T> next(std::chrono::milliseconds timeout = std::chrono::seconds(10));
    // The next event of kind E (e.g. proto::TurnEvent).
    template <class E>
    std::optional<E> next_event(std::chrono::milliseconds timeout = std::chrono::seconds(10)) {
        const auto deadline = std::chrono::steady_clock::now() + timeout;
        for (;;) {
            const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now());
            const auto event = next<proto::Event>(std::max(left, std::chrono::milliseconds(0)));
            if (!event) {
                return std::nullopt;
            }
            if (const auto* e = std::get_if<E>(&*event)) {
                return *e;
            }
        }
    }
    // The next error; its code, or "" on timeout.
    std::string next_error(std::chrono::milliseconds timeout = std::chrono::seconds(10));
    // Waits for the connection to close; returns the status detail.
    std::string wait_closed(std::chrono::milliseconds timeout = std::chrono::seconds(10));
    // Drains what arrived within `quiet` into history().
    void drain(std::chrono::milliseconds quiet);
    const std::vector<proto::ServerMessage>& history() const { return history_; }
    net::Connection& connection() { return *connection_; }

private:
    bool pull(std::chrono::steady_clock::time_point deadline);
    std::unique_ptr<net::Connection> connection_;
    std::string name_;
    std::vector<proto::ServerMessage> history_; // everything received, in order
    std::size_t cursor_ = 0;                    // history_[cursor_..] not yet handed out
};

template <class T> std::optional<T> ManualClient::next(std::chrono::milliseconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        while (cursor_ < history_.size()) {
            const auto& message = history_[cursor_++];
            if (const auto* t = std::get_if<T>(&message)) {
                return *t;
            }
        }
        if (!pull(deadline)) {
            return std::nullopt;
        }
    }
}

} // namespace carrom::integration
