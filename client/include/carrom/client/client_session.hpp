#pragma once
// The connection's life: open a link, say hello, ask for a room (create, join, spectate or quick
// match), keep pinging for the round trip and the server clock, and when the link drops, open a
// new one and resume the seat with the token, backing off between attempts. The decisions (when
// to connect, hello or resume, request, wait, give up) are net::SessionCore's, with
// ReconnectPolicy::Always (a person waits at the window); this class carries them out on a
// MessageLink and words them. Every hello says follows_redirects; a cluster's `redirect` is
// followed as the core decides (a refused one ends the session with the core's sentence).
// Game input goes out only while in a room. Messages for the match
// are handed to the caller from update().

#include "carrom/client/connection.hpp"
#include "carrom/net/session_core.hpp"
#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace carrom::client {

struct RoomRequest {
    enum class Kind { Create, Join, Spectate, Quick };
    Kind kind = Kind::Create;
    std::string code; // Join, Spectate
    proto::RuleSet rule_set = proto::RuleSet::Icf;
    // Create: server bots at bot->seats (empty: every seat but ours), at bot->level.
    std::optional<proto::BotSeat> bot;
    int seats = 2; // Create, Quick: 2 (singles) or 4 (doubles)
};

// A create or quick-match request the server would refuse for its seats (the server checks the
// same, with bad_field): seats not 2 or 4; bot seats repeated or outside 1..seats - 1 (singles:
// only seat 1). Empty if it is fine, else one sentence naming the flag.
std::string check_room_request(const RoomRequest& request);

// Connecting, Greeting, Lobby, Joining, InRoom, Reconnecting, Failed (session_core.hpp).
using SessionPhase = net::SessionPhase;

struct SessionConfig {
    double ping_interval_s = 2.0;
    net::BackoffSettings backoff; // 0.5 s doubling to 5 s; give up after 130 s
    // Each delay d drawn uniformly from [d/2, d] with this seed (so that many clients cut at
    // once do not come back at once); none: exactly d.
    std::optional<std::uint64_t> jitter_seed;
    // The player key sent in every hello (docs/ratings.md); none: a guest.
    std::optional<std::string> identity;
    // The server address the player gave: links go there, or where a cluster's redirect sends
    // them, only to this host (docs/protocol.md, "Redirects").
    std::string address;
};

// While reconnecting: what the window says ("Reconnecting... (attempt N, next try in S s)").
struct ReconnectInfo {
    int attempt = 0;          // tries so far since the loss (the next one is attempt + 1)
    double next_try_in_s = 0; // 0 while a try is connecting
    double gives_up_in_s = 0; // until the session stops trying
    bool trying = false;      // a try is connecting or saying hello
    std::string reason;       // why the link was lost, a sentence
};

class ClientSession {
public:
    ClientSession(LinkFactory factory, std::string name, const SessionConfig& config = {});

    // Opens the first link.
    void start(double local_s);
    // Ask for a room; sent as soon as the server has welcomed us (or at once if it has).
    void request(const RoomRequest& request);
    // Game input (aim, shoot, rematch): sent only while in a room.
    bool send_game(const proto::ClientMessage& message);
    // Leaves the room (sends `leave`) and goes back to the lobby on the same link. Room messages
    // still on their way are dropped until the next request.
    void leave_room();
    // Polls the link, answers the handshake, pings, reconnects; returns the messages for the match.
    std::vector<proto::ServerMessage> update(double local_s);

    SessionPhase phase() const { return core_.phase(); }
    // What the connection is doing, in plain words ("Connected", "Reconnecting (attempt 2)...").
    const std::string& status_text() const { return status_; }
    // Phase Reconnecting (or Greeting on a resuming link): the tries and the last loss's reason.
    ReconnectInfo reconnect_info(double local_s) const;
    // The seat was being resumed (bad_token): the server no longer holds it.
    bool seat_lost() const { return seat_lost_; }
    std::optional<double> rtt_ms() const { return rtt_ms_; }
    const std::string& resume_token() const { return core_.token(); }
    std::int64_t player_id() const { return player_id_; }
    // A pong's server time with the local send and receive times, for the server clock.
    struct PongSample {
        std::int64_t server_ms;
        double sent_s;
        double received_s;
    };
    std::vector<PongSample> take_pongs();

private:
    void apply(const net::SessionActions& actions);
    void open_link(double local_s);
    void on_link_lost(double local_s, const std::string& why, int close_code);
    void send_request();
    bool handle(const proto::ServerMessage& m);

    LinkFactory factory_;
    std::string name_;
    SessionConfig config_;
    net::SessionCore core_;
    std::unique_ptr<MessageLink> link_;
    bool hello_due_ = false; // the link is new: the core hears of it once it is open
    std::string status_ = "Not connected";
    std::optional<RoomRequest> request_;
    std::int64_t player_id_ = -1;
    double next_ping_s_ = 0.0;
    std::int64_t next_nonce_ = 1;
    std::map<std::int64_t, double> pings_in_flight_;
    std::optional<double> rtt_ms_;
    std::vector<PongSample> pongs_;
    std::string lost_reason_;
    double now_s_ = 0.0; // the last time given to start() or update()
    bool seat_lost_ = false;
    std::mt19937_64 jitter_;
};

} // namespace carrom::client
