#pragma once
// A headless player (or spectator) over a net::Connection: hello, then create a room, join one
// by code or ask for a quick match; on its turn it asks its strategy for a shot and sends aim,
// then shoot with the turn number; at game end it asks for a rematch until it has played
// `games` games, then leaves. After a drop, resume() reconnects with the seat's token.
//
// When to say hello, resume, reconnect and give up is net::SessionCore's decision, with
// ReconnectPolicy::SeatOnly (or Never without auto_resume): a connection that ends without the
// runner asking (network error, idle timeout, the server restarting) once it holds a room is
// resumed by itself: it reconnects with back-off and sends hello{resume_token} until the seat is
// back or config.reconnect.give_up_after_s has passed (then it fails, naming the seat). A
// bad_token answer ends it at once: the server no longer holds the seat. A connection lost
// before a room, a refused room request, version_mismatch and replaced end it too. Every hello
// says follows_redirects: a cluster's `redirect` is followed as the core decides (to the host of
// config.url only; docs/protocol.md, "Redirects"), and a refused one ends the run.
//
// Single-threaded: call step() (or run_until_done()) from one thread; the connection does the
// I/O on its own thread.

#include "carrom/bots/strategy.hpp"
#include "carrom/net/connection.hpp"
#include "carrom/net/session_core.hpp"
#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace carrom::bots {

enum class JoinMode { Create, Join, Quick, Spectate };

struct BotConfig {
    std::string url = "ws://127.0.0.1:7777";
    std::string name = "bot";
    // The player key sent in hello (net/identity_file.hpp); none: a guest.
    std::optional<std::string> identity;
    JoinMode mode = JoinMode::Quick;
    proto::CreateRoom create;                            // JoinMode::Create
    std::string code;                                    // JoinMode::Join and Spectate
    proto::RuleSet quick_rule_set = proto::RuleSet::Icf; // JoinMode::Quick
    int quick_seats = 2;                                 // JoinMode::Quick: 2, or 4 (doubles)
    int games = 1;         // games to see to the end before leaving (rematch in between)
    DecisionBudget budget; // per shot
    bool send_aim = true;  // send the striker position before each shot
    int max_refusals = 20; // refused shots in a row before giving up
    net::ConnectionOptions connection;
    bool auto_resume = true;        // resume by itself after a connection lost while in a room
    net::BackoffSettings reconnect; // its delays and how long to keep trying, in seconds
};

struct BotSummary {
    std::string room_code;
    int seat = -1; // -1: spectator or not seated
    int team = -1; // the seat's team (singles: the seat; doubles: seat % 2), -1 without a seat
    int games = 0; // games seen to the end
    int shots = 0; // shots this bot sent and the server played
    int wins = 0;  // games the seat's team won (game_end's winner is the team)
    int losses = 0;
    int draws = 0;
    std::vector<int> scores; // at the last game end, one per seat (partners share a value)
    // How the last game ended: game_end's rule, the rules engine's code the journal and the
    // Match API use ("target_points", ...); game_end's reason from a server that sends no rule;
    // "ended_while_away" when the bot came back to a game that ended meanwhile.
    std::string last_reason;
    int snapshots = 0;
    int keyframes = 0;
    int seq_gaps = 0;        // deltas whose seq did not follow the previous one (the server
                             // dropped snapshots for this slow reader)
    int unrepaired_gaps = 0; // shots that ended with no keyframe after a gap (a server bug)
    int resumes = 0;         // seats given back on a new connection (resume() or automatic)
    int redirects = 0;       // redirects followed to another instance of a cluster
    int decode_errors = 0;
    std::map<std::string, int> errors; // error codes received, with counts
    std::string failure;               // set when the bot stopped before finishing: why
    bool finished = false;             // played its games and left
};

class BotRunner {
public:
    // The strategy must outlive the runner.
    BotRunner(BotConfig config, Strategy& strategy);
    ~BotRunner();
    BotRunner(const BotRunner&) = delete;
    BotRunner& operator=(const BotRunner&) = delete;

    // Opens the connection and sends hello.
    void start();
    // Waits up to `wait` for messages and handles them; returns done().
    bool step(std::chrono::milliseconds wait);
    // Steps until done or the timeout passes; returns done().
    bool run_until_done(std::chrono::milliseconds timeout);
    // Finished its games, or failed.
    bool done() const { return summary_.finished || !summary_.failure.empty(); }

    // Drops the connection without leaving (the seat is kept for the server's grace period).
    void drop();
    // Reconnects and sends hello with the resume token.
    void resume();

    // Called for every message received, before the runner reacts to it (tests, load tools).
    std::function<void(const proto::ServerMessage&)> on_message;
    // Called with a sentence when the connection is lost, on each try to resume, and when the
    // seat is back (carrom-bot logs them).
    std::function<void(const std::string&)> on_notice;
    // Called right after each shoot is handed to the connection (carrom-bot --trace).
    std::function<void(const proto::Shoot&)> on_shoot;
    // Makes the connection for start(), resume() and redirects (the config's url is where this
    // connection goes); default: net::Connection::open(url).
    std::function<std::unique_ptr<net::Connection>(const BotConfig&)> connect;

    const BotSummary& summary() const { return summary_; }
    const std::optional<proto::RoomState>& room() const { return room_; }
    const std::string& resume_token() const { return core_.token(); }
    net::Connection* connection() { return connection_.get(); }

private:
    void handle(const proto::ServerMessage& message);
    void on_welcome(const proto::Welcome& welcome);
    void on_room_state(const proto::RoomState& room);
    void on_snapshot(const proto::Snapshot& snapshot);
    void on_event(const proto::Event& event);
    void on_shot_result(const proto::ShotResult& result);
    void on_error(const proto::Error& error);
    void on_redirect(const proto::Redirect& redirect);
    void on_game_end(const proto::GameEndEvent& end);
    void send_room_request();
    // Carries out the session core's actions; `error`: the error they answer, if any.
    void apply(const net::SessionActions& actions, const proto::Error* error = nullptr);
    void open_connection();
    double now_s() const; // seconds since the runner was made
    void maybe_play();
    void fail(std::string why);
    void connection_lost(const net::ConnectionStatus& status);
    std::string seat_words() const;
    void notice(const std::string& text);

    BotConfig config_;
    Strategy& strategy_;
    std::unique_ptr<net::Connection> connection_;
    net::SessionCore core_;
    std::chrono::steady_clock::time_point epoch_ = std::chrono::steady_clock::now();
    std::mt19937_64 jitter_{std::random_device{}()}; // draws each try's place in [d/2, d]
    bool dropped_ = false;
    std::optional<proto::RoomState> room_;
    int last_played_turn_ = -1; // turn number of the last shot sent in this game
    int refusals_ = 0;          // refused shots in a row
    std::int64_t last_seq_ = -1;
    bool awaiting_keyframe_ = false; // a gap was seen; the board is stale until a keyframe
    BotSummary summary_;
    std::string lost_reason_; // why the last connection (or try) ended
};

} // namespace carrom::bots
