#pragma once
// The client side of a session's life, without I/O or clocks: when to open a link, whether hello
// carries the resume token, when to send the room request, how long to wait before the next try,
// and when to stop. carrom-client's ClientSession and carrom-bot's BotRunner drive it; the web
// client's web/js/session_core.js is its port, and both replay tests/golden/session/*.json
// (written from this class by carrom-session-golden; tests/golden/README.md).
//
// The caller reports events (with the time, in seconds on any monotonic clock, where it
// matters: link_closed() and tick()) and carries out the actions each call returns, in order:
// - Connect: open a new link to url() (the previous one is gone, or the caller closes it and
//   reports nothing more of it); report link_opened() or link_closed().
// - SendHello / SendResume: hello without / with token() (the seat is asked back).
// - SendRoomRequest: the caller's room request (create, join, spectate, quick match).
// - SendJoin: join_room{join_code(), join_as()}, the room a redirect named.
// - SendLeave: leave the room (the session is in the lobby).
// - Wait: the link is gone; tick() returns Connect once wait_s has passed.
// - Resumed: the seat is back (the room's state after a resume).
// - SeatLost: the server no longer holds the seat (bad_token, or a resume welcomed with another
//   token): the session is in the lobby as a new player, with no room request.
// - Refused: the room request was refused (room_not_found, room_full, unsupported,
//   too_many_rooms, bad_field, already_in_room): the session is in the lobby.
// - GiveUp: the session ends (phase Failed); the caller closes the link. start() begins again.
//
// The rules, the same for every client:
// - A link that ends without the caller asking is tried again, with back-off: the n-th try of one
//   loss waits d = min(first_s * 2^(n-1), cap_s), scaled to [d/2, d] by the caller's uniform draw
//   `jitter` in [0, 1] (1: exactly d), so that clients cut at once do not return at once. The
//   loss lasts until the session is back where it was (welcome for a session without a seat,
//   the room's state for a resume); its tries stop give_up_after_s after it began, and the last
//   try is made at that instant, not after it.
// - The seat is asked back (SendResume) when the link was lost in a room or during a resume;
//   a request not yet answered (create, join, quick match) is sent again on the new link by a
//   new player: a quick-match queue or a room not yet shown to us is no seat to resume.
// - Which clients reconnect (ReconnectPolicy): carrom-client and the web page always, a person
//   waiting at the screen; carrom-bot only to resume a seat (a program started against a wrong
//   address fails at once), or never (--resume-for 0).
// - Final: version_mismatch (error, or close 4001) and replaced (error, or close 4002: the seat
//   was resumed on another link; trying again would take it back and forth). Anything else
//   (idle_timeout and close 1008, shutting_down and close 1012, close 1006, 1013, 4003, a silent
//   link) is a loss and is tried again. match_moving (then close 1013) is tried again under
//   SeatOnly too: the address is right, the match is between instances.
// - Redirects (docs/protocol.md, "Redirects"): a `redirect` is followed when redirect_allowed()
//   (same host as the address the player gave, ws:// or wss://, no downgrade from wss://) and it
//   is at most the kMaxRedirects-th in a row (since the session was last in a room or the lobby,
//   or lost a link): Connect to its URL at once, no back-off, hello with the token when the
//   session holds a seat, then SendJoin when the redirect names a room and no seat came back.
//   The server's close 4005 that follows is no loss. Otherwise GiveUp (RedirectRefused): the
//   session never connects there. A loss always tries the address the player gave again, which
//   sends the client on to wherever the match runs.

#include "carrom/proto/server_messages.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace carrom::net {

struct BackoffSettings {
    double first_s = 0.5; // the first try's delay; each further try doubles it
    double cap_s = 5.0;   // up to this
    // How long after the loss to keep trying: the server's default idle timeout (60 s, after
    // which it notices a link that went silent) plus its grace period (60 s) plus a margin.
    double give_up_after_s = 130.0;
};

enum class ReconnectPolicy {
    Always,   // after any loss (a person waits at the screen)
    SeatOnly, // only to resume a seat; a loss without one gives up (NoRetry)
    Never,    // every loss gives up (NoRetry)
};

// The client's phases; the web client's names are in session_phase_name().
enum class SessionPhase {
    Connecting,   // a link is opening, or waiting for its next try, before any welcome
    Greeting,     // hello sent, waiting for welcome
    Lobby,        // welcomed, no room asked for (or the request was answered with no)
    Joining,      // room asked for (or resumed), waiting for its state
    InRoom,       // the room's state received
    Reconnecting, // welcomed before: the link is gone and a new one is waiting or opening
    Failed,       // given up
};

enum class SessionActionKind {
    Connect,
    SendHello,
    SendResume,
    SendRoomRequest,
    SendJoin,
    SendLeave,
    Wait,
    Resumed,
    SeatLost,
    Refused,
    GiveUp,
};

enum class GiveUpReason {
    NoRetry,         // the policy does not reconnect after this loss
    TimeUp,          // give_up_after_s passed since the loss
    VersionMismatch, // the server speaks another protocol version
    Replaced,        // the seat was resumed on another link
    RedirectRefused, // a redirect to an address that is not the cluster's (or one too many)
};

struct SessionAction {
    SessionActionKind kind = SessionActionKind::Connect;
    double wait_s = 0.0;                         // Wait: seconds until the next try
    GiveUpReason reason = GiveUpReason::NoRetry; // GiveUp
    friend bool operator==(const SessionAction&, const SessionAction&) = default;
};

using SessionActions = std::vector<SessionAction>;

class SessionCore {
public:
    // Redirects in a row a session follows; the next one is refused.
    static constexpr int kMaxRedirects = 3;

    // address: the server address the player gave (ws://HOST:PORT[/path]); links go there, or
    // where a redirect sends them (url()).
    explicit SessionCore(BackoffSettings backoff = {},
                         ReconnectPolicy policy = ReconnectPolicy::Always,
                         std::string address = {});

    // Begins (or begins again, after GiveUp or a drop of the caller's own): Connect. With a
    // token, hello asks for that token's seat back (a reload of the web page, BotRunner::resume()).
    SessionActions start(const std::string& resume_token);
    // The caller wants a room: sent now if in the lobby, else once welcomed.
    SessionActions request();
    // Leave the room (or the quick-match queue): SendLeave if in one, and no room request.
    SessionActions leave();

    SessionActions link_opened();
    // The link ended without the caller asking. close_code: the server's close frame's code, 0
    // without one; jitter: a uniform draw in [0, 1] for this try's delay.
    SessionActions link_closed(double now_s, int close_code, double jitter);
    // Time passed: Connect once a Wait is over.
    SessionActions tick(double now_s);

    SessionActions welcome(const std::string& token);
    SessionActions room_state();
    SessionActions error(std::string_view code);
    // A `redirect` on the current link: Connect (to its URL) or GiveUp (RedirectRefused).
    SessionActions redirect(const proto::Redirect& message);

    SessionPhase phase() const { return phase_; }
    // A room's messages in the lobby come from a room we left (or lost): the caller drops them.
    bool drops_room_messages() const { return phase_ == SessionPhase::Lobby; }
    const std::string& token() const { return token_; }
    bool resuming() const { return resuming_; }
    bool wants_room() const { return wants_room_; }
    bool link_up() const { return link_up_; } // between Connect and link_closed() or GiveUp
    // The current loss: tries so far (0: none), when it began, when the next try is due.
    int tries() const { return tries_; }
    double lost_since_s() const { return lost_since_s_; }
    double retry_at_s() const { return retry_at_s_; }
    double gives_up_at_s() const { return lost_since_s_ + backoff_.give_up_after_s; }
    const BackoffSettings& backoff() const { return backoff_; }
    const std::string& address() const { return address_; }
    const std::string& url() const { return url_; }             // where Connect goes
    int redirects() const { return redirects_; }                // followed in a row
    const std::string& join_code() const { return join_code_; } // SendJoin's room, or empty
    proto::Role join_as() const { return join_as_; }
    // After GiveUp (RedirectRefused): one sentence saying which redirect and why, starting
    // "redirect refused: ".
    const std::string& refused_redirect() const { return refused_redirect_; }

private:
    SessionActions give_up(GiveUpReason reason);
    SessionActions give_up_seat();
    void end_loss();
    void back_in_room_or_lobby(); // the redirects in a row start again

    BackoffSettings backoff_;
    ReconnectPolicy policy_;
    std::string address_;
    SessionPhase phase_ = SessionPhase::Connecting;
    std::string token_;
    bool resuming_ = false;      // hello carries the token; cleared by the room's state
    bool wants_room_ = false;    // a room request not yet answered by a room or a refusal
    bool ever_welcomed_ = false; // since start()
    bool link_up_ = false;
    bool waiting_ = false; // for retry_at_s_
    int tries_ = 0;
    std::string url_;                 // the current (or next) link's URL: address_ or a redirect's
    int redirects_ = 0;               // followed since the session was last in a room or the lobby
    bool redirect_close_due_ = false; // the redirected link's close (4005) is still to come
    bool retry_next_loss_ = false;    // match_moving: the next loss is tried again
    std::string refused_redirect_;
    std::string join_code_; // a redirect's room, joined when no seat comes back
    proto::Role join_as_ = proto::Role::Player;
    double lost_since_s_ = 0.0;
    double retry_at_s_ = 0.0;
};

// The names in golden files and the web client ("connecting", "in_room", "send_resume",
// "time_up", ...); session_core.cpp lists them in the enumerators' order.
std::string_view session_phase_name(SessionPhase phase);
std::string_view session_action_name(SessionActionKind kind);
std::string_view give_up_reason_name(GiveUpReason reason);

} // namespace carrom::net
