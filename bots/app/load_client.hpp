#pragma once
// carrom-load's clients: many light WebSocket players on one io_context (one thread), so that
// thousands of them cost the machine little next to the server being measured. Every message's
// head is read first (message_head.hpp): of a snapshot only the fields the lag figures need;
// the messages a player acts on are then decoded whole with proto::decode_server.

#include "load_redirect.hpp"

#include "carrom/bots/random_strategy.hpp"
#include "carrom/proto/client_messages.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/context.hpp>

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace carrom::load {

using Clock = std::chrono::steady_clock;

// What clients count, summed over them (one thread: no locking).
struct LoadCounts {
    std::int64_t messages = 0; // received, every kind
    std::int64_t bytes = 0;    // received payload bytes
    std::int64_t snapshots = 0;
    // Received messages whose head (message_head.hpp) or, for those a player acts on, whole
    // text did not decode.
    std::int64_t malformed = 0;
    std::int64_t shots = 0;             // shot_result received by the shooter
    std::int64_t errors = 0;            // error messages received
    std::int64_t failures = 0;          // connections that broke or never opened
    std::int64_t redirects = 0;         // a cluster's redirects followed (a new connection each)
    std::int64_t redirects_refused = 0; // redirects not followed (counted in failures too)
    std::int64_t matches_started = 0;   // pairs whose creator began to connect
    std::int64_t matches_finished = 0;  // games that ended (game_end), counted once per match
    LoadCounts& operator+=(const LoadCounts& other);
};

// What clients measure, summed over them (one thread: no locking).
struct LoadStats : LoadCounts {
    std::map<std::string, std::int64_t> errors_by_code; // error messages received, by code
    std::string tls_refusal;      // the first refused TLS handshake's sentence (client_tls.hpp)
    std::string redirect_refusal; // the first refused redirect's sentence
    // Per delta snapshot: receive time - the time the room's schedule had it due (due_ms), ms.
    std::vector<double> lag_ms;
    std::vector<std::int64_t> lag_due_ms; // due_ms of each lag_ms sample, for the timeline
    // Per delta snapshot: its delivery delay beyond the fastest snapshot of the same shot, ms
    // (receive time - match time t, minus the smallest such value of the shot).
    std::vector<double> relative_lag_ms;
    double moving_bytes = 0.0;   // bytes received while the client's board moved
    double moving_seconds = 0.0; // summed over clients
    bool measuring = false;      // lags and bytes counted only inside the window
    // Adds the other's counts and samples (measuring stays as it is).
    LoadStats& operator+=(const LoadStats& other);
};

struct LoadOptions {
    boost::asio::ip::tcp::endpoint server;
    // wss: TLS with this client context, the certificate checked for the server's IP address;
    // null: plain ws.
    std::shared_ptr<boost::asio::ssl::context> tls;
    proto::RuleSet rule_set = proto::RuleSet::Freestyle;
    std::chrono::milliseconds think{0}; // delay before each shot
    // Each delay is drawn uniformly from [think - think_spread, think + think_spread] (players
    // are not in step); 0: every delay is exactly `think`.
    std::chrono::milliseconds think_spread{0};
    int target_points = 1000; // of each room: 1000 makes the game last a whole run
    // At the end of a game both players leave and a new match takes its place (false: they
    // play a rematch in the same room).
    bool replace = false;
    // Keep the per-snapshot lag samples (about 24 bytes per snapshot); false for long runs,
    // whose lag figures are then 0.
    bool keep_samples = true;
};

// Two players of one room. The creator makes the room; the joiner starts once it has a code.
// With LoadOptions::replace the pair is a slot: when its game ends both players leave and two
// new players start a new match in a new room (a new generation).
class MatchPair {
public:
    MatchPair(boost::asio::io_context& ioc, const LoadOptions& options, LoadStats& stats,
              std::uint64_t seed);
    ~MatchPair();
    void start();
    // Both seated and connected, the game going.
    bool held() const;
    void close();

    // Shared between the two players: when the current shot was sent (for lag).
    Clock::time_point shot_sent_at{};
    int shot_turn = -1;

    void on_room_code(int generation, const std::string& code); // from the creator
    void on_game_end(int generation);                           // from either player
    class Player;
    // A player got a redirect it follows: a new player of the same role takes its place there.
    void on_redirect(const Player* from, const RedirectPlan& plan);

private:
    boost::asio::io_context& ioc_;
    LoadOptions options_;
    LoadStats& stats_;
    std::shared_ptr<Player> creator_;
    std::shared_ptr<Player> joiner_;
    std::uint64_t seed_;
    int generation_ = 0; // matches started in this slot
};

} // namespace carrom::load
