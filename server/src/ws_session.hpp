#pragma once
// Private to server/src: one WebSocket connection. Reads and validates client messages, keeps
// session-level state (hello, rate limit, timeouts, the quick-match wait), forwards game input to
// its room's strand, and writes through a bounded queue (one write in flight). Every member is
// touched only on the session's strand, except the Peer interface, which posts to it.
// ws_session.cpp: the connection (accept, read, dispatch, write queue, keep-alive, end);
// ws_session_lobby.cpp: hello, create, join, quick match, entering a room.

#include "rated_queue.hpp"
#include "server_stream.hpp"

#include "carrom/server/registry.hpp"
#include "store/cluster.hpp"

#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/error.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/room/peer.hpp"
#include "carrom/server/rate_limiter.hpp"
#include "carrom/server/write_queue.hpp"

#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace carrom::server {

class RoomActor;
struct ServerCore;

// Sent with shutting_down before close 1012 "restarting" (SIGINT/SIGTERM).
inline constexpr const char* kRestartingText =
    "The server is restarting; reconnect with your resume token.";

// A close that does not finish within this is cut off (the socket is closed).
inline constexpr std::chrono::milliseconds kCloseDeadline{3000};

class WsSession final : public room::Peer, public std::enable_shared_from_this<WsSession> {
public:
    WsSession(ServerCore& core, ServerStream stream);
    ~WsSession() override;

    void run(http::request<http::string_body> request);

    // Peer
    std::int64_t player_id() const override { return player_id_; }
    const std::string& name() const override { return name_; }
    std::string resume_token() const override { return token_; }
    void send(room::Outgoing message) override;
    bool take_keyframe_request() override { return keyframe_request_.exchange(false); }
    void close(int close_code, std::string reason) override;

    // Quick match paired this session into a room (any thread).
    void assign_room(std::shared_ptr<RoomActor> room);
    // Forgets the room (Server::shutdown, once the I/O threads are joined): a room holds its
    // members and a member its room, and a session still open at the end would keep both.
    void release_room() { room_.reset(); }
    // Server shutdown (any thread).
    void shutdown();
    // Cluster mode (any thread). Another instance paired this session's quick-match ticket.
    void on_quick_paired(store::QuickPairing pairing);
    // A draining instance handed this session's room to another instance: the client goes
    // there (url_by_room: room code to the instance's URL); any other session gets
    // shutting_down, as at shutdown().
    void move_or_shutdown(
        std::shared_ptr<const std::unordered_map<std::string, std::string>> url_by_room);

private:
    void on_accept(beast::error_code ec);
    void do_read();
    void on_read(beast::error_code ec, std::size_t bytes);
    void handle_text(std::string_view text);
    void handle(const proto::ClientMessage& message);
    void handle_hello(const proto::Hello& hello);
    // The welcome of a hello (record: the resumed seat's player; none: a new player, after
    // bad_token for a token the hello had, unless say_bad_token is false: said already).
    void finish_hello(const proto::Hello& hello, std::optional<PlayerRecord> record,
                      bool say_bad_token);
    void handle_create(const proto::CreateRoom& create);
    void handle_join(const proto::JoinRoom& join);
    void handle_quick_match(const proto::QuickMatch& quick);
    // Starts the bot fallback timer of a quick-match wait, unless one runs (or bots are off).
    void arm_quick_match_wait(proto::RuleSet rule_set, int seats);
    // Leaves the quick-match queue and stops the bot fallback timer.
    void stop_quick_match();
    void on_quick_match_wait(std::uint64_t generation, proto::RuleSet rule_set, int seats);
    // ws_session_rated.cpp: identities and rated rooms (docs/ratings.md).
    // The hello's identity or a guest's name: true when the hello may go on (else refused).
    bool admit_hello_identity(const proto::Hello& hello);
    // create_room with rated: why not (rated_with_bot, rated_doubles, identity_required).
    std::optional<proto::Error> rated_refusal(const proto::CreateRoom& create) const;
    // A rated room's seat for this session: why not (identity_required, same_player).
    std::optional<proto::Error> rated_seat_refusal(RoomActor& room) const;
    // Quick match of an identified player in singles: the rated queue, paired by rating.
    void handle_rated_quick_match(const proto::QuickMatch& quick);
    void arm_rated_tick(std::uint64_t generation);
    // Pairs the closest acceptable two of rule_set's rated queue into a new rated room: true
    // when this player was one of them (taken out of the queue).
    bool try_rated_pair(proto::RuleSet rule_set);
    // The rated wait ran out: a bot (an unrated room), if still waiting.
    void on_rated_wait_over(proto::RuleSet rule_set);
    // A new room of `seats` seats with this player in seat 0, `others` (quick match) in the first
    // free seats after it and server bots of `level` in `bot_seats` (create_room with bot, or
    // the quick-match wait ran out).
    void enter_bot_room(proto::RuleSet rule_set, const proto::RoomOptions& options, int seats,
                        proto::BotLevel level, const std::vector<int>& bot_seats,
                        const std::vector<std::shared_ptr<WsSession>>& others = {});
    void enter_room(const std::shared_ptr<RoomActor>& room, proto::Role role);
    // The room refused this session's join or resume (called on the room's strand): the client
    // gets the error, and the session forgets the room unless it has entered another meanwhile.
    void on_room_refused(const std::shared_ptr<RoomActor>& room, const proto::Error& error);
    // ws_session_cluster.cpp: cluster mode (docs/cluster.md, "Rooms across the cluster").
    // `redirect` for a client that follows it (then close 4005).
    void redirect(proto::Redirect to);
    // `where`, or Moving when it names the instance whose route the front was asked for (the
    // front could not reach it and sent the client here).
    store::RoomLocation reachable(store::RoomLocation where) const;
    // join_room of a room not here, hello with a resume token not known here: asks the
    // cluster's directory, answers on the strand (redirect, room_elsewhere/seat_elsewhere,
    // match_moving, or as a server alone would).
    void locate_room(const proto::JoinRoom& join);
    void on_room_located(const proto::JoinRoom& join,
                         const store::Loaded<store::RoomLocation>& located);
    void locate_seat(const proto::Hello& hello);
    void on_seat_located(const proto::Hello& hello,
                         const store::Loaded<store::RoomLocation>& located);
    // Quick match across instances: a ticket in the cluster (singles, a client that follows
    // redirects; a rated player's with its rating), withdrawn with the local wait. A rated
    // player's ticket is asked again at each rated tick (its acceptable gap widens).
    void enqueue_in_cluster(proto::RuleSet rule_set);
    // A room of a pairing with a player of another instance, hosted here with this player in
    // seat 0 (rated: a rated room); the partner's seat goes to a bot if it has not come when the
    // quick-match wait is over (rated: this player leaves for a room against a bot).
    void host_cluster_pairing(proto::RuleSet rule_set, const std::string& code, bool rated);
    void on_cluster_enqueued(std::uint64_t generation, proto::RuleSet rule_set,
                             const store::Loaded<store::QuickEnqueued>& enqueued);
    void withdraw_cluster_ticket();
    void send_now(room::Outgoing message);
    void send_error(std::string_view code, std::string message);
    void fail(std::string_view code, std::string message, int close_code);
    void begin_close(int close_code, std::string reason,
                     std::chrono::milliseconds deadline = kCloseDeadline);
    void do_write();
    void on_write(beast::error_code ec, std::size_t bytes);
    void arm_idle_timer();
    void on_idle_timer();
    void end();

    ServerCore& core_;
    beast::websocket::stream<ServerStream> ws_;
    beast::flat_buffer buffer_;
    asio::steady_timer hello_timer_;
    asio::steady_timer idle_timer_;
    asio::steady_timer kill_timer_;
    asio::steady_timer quick_timer_; // quick match: seat a bot when it fires
    std::uint64_t quick_generation_ = 0;
    bool quick_waiting_ = false;
    asio::steady_timer rated_timer_; // rated quick match: try pairing again every second
    bool rated_waiting_ = false;     // in core_.rated_queue (quick_generation_ counts its waits)
    proto::RuleSet rated_rule_set_ = proto::RuleSet::Icf;
    double rated_rating_ = 0.0; // points: the waiting rated player's rating in rated_rule_set_
    WriteQueue queue_;
    RateLimiter limiter_;
    std::atomic<bool> keyframe_request_{false};

    bool accepted_ = false;
    bool hello_done_ = false;
    bool ended_ = false;
    bool ping_in_flight_ = false;
    std::optional<int> close_code_; // a close was requested
    std::string close_reason_;
    bool close_started_ = false;
    std::string address_;          // the client's IP address (client_address.hpp)
    std::string forwarded_for_;    // the upgrade request's X-Forwarded-For
    std::string route_asked_;      // X-Carrom-Route: the instance the front was asked for (/i/ID/)
    bool address_counted_ = false; // counted in ServerCore::connections_by_address
    bool too_slow_ = false;        // the write queue overflowed: nothing more is queued
    std::int64_t last_activity_ms_ = 0;

    std::int64_t player_id_ = -1;
    std::optional<store::PlayerKeyHash> identity_; // sha256 of the hello's key; none: a guest
    std::string name_;
    std::string token_;
    std::shared_ptr<RoomActor> room_;
    proto::Role role_ = proto::Role::Player; // in room_

    // Cluster mode.
    bool follows_redirects_ = false;             // the hello said so
    bool hello_pending_ = false;                 // a resume's seat is being located: input waits
    std::vector<proto::ClientMessage> deferred_; // input that came while hello_pending_
    bool ticket_pending_ = false;                // a quick-match ticket is being enqueued
    std::uint64_t ticket_generation_ = 0; // counts stop_quick_match: an older answer is stale
    std::int64_t ticket_ = 0;             // this session's quick-match ticket in the cluster, or 0
    asio::steady_timer partner_timer_;    // a paired room: a bot takes the partner's seat if due
};

} // namespace carrom::server
