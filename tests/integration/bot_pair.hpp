#pragma once
// Two bots in one room of a carrom-server process (the in-process BotRunner over real sockets),
// for the recovery and cluster tests: the creator makes an ICF room of one board with a 4 s shot
// clock, the joiner joins it. The bots reach the server at a URL the test can move (move_to: the
// next connection, a resume included, goes there), as a player's client reaches another
// instance after a takeover.

#include "harness.hpp"

#include "support/server_process.hpp"

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

namespace carrom::integration {

struct Pair {
    // rated: the bots say hello with player keys (64 hex digits: all 'c', all 'f') and the room
    // is rated (docs/ratings.md).
    Pair(const std::string& url, std::uint64_t seed, bool rated = false);

    // Steps both bots until `until` or both are done or the timeout passes.
    void run(const std::function<bool()>& until, std::chrono::milliseconds timeout);
    void drop();
    void resume();
    // Where the bots connect from now on.
    void move_to(const std::string& url);
    std::string url() const;
    // Both finished their game, each resumed `resumes` times, never with bad_token.
    void expect_finished(int resumes = 1) const;

    std::unique_ptr<bots::Strategy> first;
    std::unique_ptr<bots::Strategy> second;
    std::unique_ptr<bots::BotRunner> creator;
    std::unique_ptr<bots::BotRunner> joiner;
    std::atomic<int> shots{0}; // strokes the creator saw played (shot_result)
    std::function<void(const proto::ServerMessage&)> hook;

private:
    mutable std::mutex url_mutex_;
    std::string url_;
};

// What a bot saw of its match pausing while the store did not answer (docs/cluster.md, "The
// database down"); fed every message (Pair::hook).
struct PauseWatch {
    void see(const proto::ServerMessage& m);

    int paused = 0;
    int resumed = 0;
    int streamed_while_paused = 0; // snapshots and shot results between `paused` and `resumed`
    std::string reason;            // of the last `paused`
    std::string message;           // of the last `paused`
    std::chrono::steady_clock::time_point paused_at;  // of the last `paused`
    std::chrono::steady_clock::time_point resumed_at; // of the last `resumed`
};

// A new client's create_room (also against bots) and quick_match: each answered
// store_unavailable.
void expect_new_matches_refused(const std::string& url);

// carrom-server's options for bot pairs on data: playback 25 times faster, a 20 s grace period,
// info logs, 1,000 connections per address.
test_support::ServerProcess::Options bot_server_options(const std::string& data);

// Every match the creator played on the server: finished, and its journal replays clean with
// consecutive turns. Returns the strokes.
int expect_finished_journals_clean(const test_support::ServerProcess& server, std::size_t count);

} // namespace carrom::integration
