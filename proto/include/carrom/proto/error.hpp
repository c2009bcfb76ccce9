#pragma once
// The one error type of proto/: a stable machine-readable code, one plain sentence and, for a
// problem inside a JSON document, the path of the offending value. Wire messages carry it as the
// "error" message (code and message; docs/protocol.md lists every code and when it is sent);
// documents (scenes, results, match states, journals) report it with its path (error_to_json;
// docs/carrom-sim.md lists their codes). Also the WebSocket close codes the server uses.

#include <string>
#include <string_view>

namespace carrom::proto {

struct Error {
    std::string code; // a constant of namespace code or scene_code, or another documented
                      // code ("overlap", "inconsistent_state", ...); stable: callers switch on it
    std::string message; // one plain sentence for people; may change between versions
    // Where in a decoded JSON document: "config.disc_restitution", "bodies[3].vel.x"; "" for the
    // document as a whole and for errors that are not about a value. Not sent on the wire (the
    // "error" message's sentence names the field instead).
    std::string path = {};
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
// Identities and rated rooms (docs/ratings.md).
inline constexpr std::string_view kBadIdentity = "bad_identity"; // not 64 lowercase hex digits
inline constexpr std::string_view kNameTaken = "name_taken";     // another identity holds the name
inline constexpr std::string_view kTooManyIdentities =
    "too_many_identities"; // new identities from one address over the limit per minute
inline constexpr std::string_view kIdentityRequired =
    "identity_required"; // a rated room asked for or joined without an identity
inline constexpr std::string_view kRatedWithBot = "rated_with_bot"; // rated and a bot seat
inline constexpr std::string_view kRatedDoubles = "rated_doubles";  // rated with 4 seats
inline constexpr std::string_view kSamePlayer =
    "same_player"; // the identity already holds the other seat of this rated room
// Rooms.
inline constexpr std::string_view kRoomNotFound = "room_not_found";
inline constexpr std::string_view kRoomFull = "room_full";
inline constexpr std::string_view kAlreadyInRoom = "already_in_room";
inline constexpr std::string_view kNotInRoom = "not_in_room";
// Cluster mode (docs/cluster.md).
inline constexpr std::string_view kRoomElsewhere =
    "room_elsewhere"; // the room runs on another instance; the message names its URL
inline constexpr std::string_view kSeatElsewhere =
    "seat_elsewhere"; // the resumed seat's match runs on another instance (URL in the message)
inline constexpr std::string_view kMatchMoving =
    "match_moving"; // the match's instance stopped; another takes it over: try again shortly
inline constexpr std::string_view kStoreUnavailable =
    "store_unavailable"; // the match store does not answer: no new room until it does
// Game input.
inline constexpr std::string_view kSpectator = "spectator"; // spectators send no game input
inline constexpr std::string_view kNotYourTurn = "not_your_turn";
inline constexpr std::string_view kStaleTurn = "stale_turn";   // turn number is not the current
inline constexpr std::string_view kInMotion = "in_motion";     // a shot is still being played
inline constexpr std::string_view kWrongPhase = "wrong_phase"; // e.g. shoot before both seated
inline constexpr std::string_view kIllegalPlacement = "illegal_placement";
inline constexpr std::string_view kIllegalShot = "illegal_shot";
inline constexpr std::string_view kEmoteTooFast =
    "emote_too_fast"; // a seat's emotes over the room's rate; that emote is dropped
inline constexpr std::string_view kUnsupported = "unsupported"; // e.g. bot seats without bots
inline constexpr std::string_view kInternal = "internal";
} // namespace code

// Codes of documents: scenes, results, match states and journals (docs/carrom-sim.md).
namespace scene_code {
inline constexpr std::string_view kMalformedJson = "malformed_json"; // not JSON, number overflow
inline constexpr std::string_view kTooLarge = "too_large";           // text over its size limit
inline constexpr std::string_view kTooDeep = "too_deep";             // nesting over kMaxJsonDepth
inline constexpr std::string_view kDuplicateKey = "duplicate_key";   // a key twice in one object
inline constexpr std::string_view kWrongType = "wrong_type";         // e.g. a string for a number
inline constexpr std::string_view kMissingField = "missing_field";
inline constexpr std::string_view kUnknownField = "unknown_field";
inline constexpr std::string_view kNotFinite = "not_finite";
inline constexpr std::string_view kOutOfRange = "out_of_range";
inline constexpr std::string_view kBadValue = "bad_value";           // e.g. an unknown body kind
inline constexpr std::string_view kTooMany = "too_many";             // more than kMaxSceneBodies
inline constexpr std::string_view kConflict = "conflicting_fields";  // "bodies" and "layout"
inline constexpr std::string_view kInvalidConfig = "invalid_config"; // validate_config failed
// validate_scene failures keep their own codes: "duplicate_id", "not_finite",
// "outside_cushions", "overlap".
} // namespace scene_code

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
inline constexpr int kCloseMatchMoved = 4004;      // another instance took the match over: resume
inline constexpr int kCloseRedirected = 4005;      // after a `redirect`: connect to its URL

} // namespace carrom::proto
