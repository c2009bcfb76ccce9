#pragma once
// Errors on the wire: a stable machine-readable code plus one plain sentence, and the WebSocket
// close codes the server uses. docs/protocol.md lists every code and when it is sent.

#include <string>
#include <string_view>

namespace carrom::proto {

struct Error {
    std::string code;    // one of the constants in namespace code (stable; clients switch on it)
    std::string message; // one plain sentence for people; may change between versions
    friend bool operator==(const Error&, const Error&) = default;
};

namespace code {
// Decoding (any message).
inline constexpr std::string_view kMalformedJson =
    "malformed_json";                                            // not JSON, or a number overflows
inline constexpr std::string_view kTooLarge = "too_large";       // text over the size limit
inline constexpr std::string_view kNotObject = "not_object";     // top level is not an object
inline constexpr std::string_view kMissingType = "missing_type"; // no string "type" field
inline constexpr std::string_view kUnknownType = "unknown_type"; // "type" names no message
inline constexpr std::string_view kBadField = "bad_field";       // a field's type, range, size
inline constexpr std::string_view kBinaryFrame = "binary_frame"; // only text frames are used
// Session.
inline constexpr std::string_view kVersionMismatch = "version_mismatch";
inline constexpr std::string_view kHelloRequired = "hello_required"; // first message must be hello
inline constexpr std::string_view kAlreadyHello = "already_hello";
inline constexpr std::string_view kBadToken = "bad_token"; // resume token unknown/expired
inline constexpr std::string_view kRateLimited = "rate_limited";
inline constexpr std::string_view kServerFull = "server_full"; // max connections reached
inline constexpr std::string_view kTooManyConnections =
    "too_many_connections"; // max connections from one client address reached
inline constexpr std::string_view kTooManyRooms = "too_many_rooms";
inline constexpr std::string_view kHandshakeTimeout = "handshake_timeout";
inline constexpr std::string_view kIdleTimeout = "idle_timeout";
inline constexpr std::string_view kShuttingDown = "shutting_down";
inline constexpr std::string_view kReplaced = "replaced"; // the seat was resumed on another link
// Rooms.
inline constexpr std::string_view kRoomNotFound = "room_not_found";
inline constexpr std::string_view kRoomFull = "room_full";
inline constexpr std::string_view kAlreadyInRoom = "already_in_room";
inline constexpr std::string_view kNotInRoom = "not_in_room";
// Game input.
inline constexpr std::string_view kSpectator = "spectator"; // spectators send no game input
inline constexpr std::string_view kNotYourTurn = "not_your_turn";
inline constexpr std::string_view kStaleTurn = "stale_turn";   // turn number is not the current
inline constexpr std::string_view kInMotion = "in_motion";     // a shot is still being played
inline constexpr std::string_view kWrongPhase = "wrong_phase"; // e.g. shoot before both seated
inline constexpr std::string_view kIllegalPlacement = "illegal_placement";
inline constexpr std::string_view kIllegalShot = "illegal_shot";
inline constexpr std::string_view kUnsupported = "unsupported"; // e.g. bot seats without bots
inline constexpr std::string_view kInternal = "internal";
} // namespace code

// WebSocket close codes (RFC 6455 section 7.4 plus the application range 4000-4999).
inline constexpr int kCloseNormal = 1000;          // leave, or server-side normal end
inline constexpr int kCloseGoingAway = 1001;       // going away (not sent by this server)
inline constexpr int kCloseUnsupportedData = 1003; // binary frame
inline constexpr int kClosePolicy = 1008;          // rate limit, limits, handshake/idle timeout
inline constexpr int kCloseTooBig = 1009;          // frame over the size limit
inline constexpr int kCloseInternal = 1011;        // server bug
inline constexpr int kCloseRestarting = 1012; // SIGINT/SIGTERM: reconnect and resume, with backoff
inline constexpr int kCloseTryAgainLater = 1013;   // server full
inline constexpr int kCloseVersionMismatch = 4001; // hello with another protocol version
inline constexpr int kCloseReplaced = 4002;        // the seat was resumed on another connection
inline constexpr int kCloseSlowClient = 4003;      // write queue bound exceeded

} // namespace carrom::proto
