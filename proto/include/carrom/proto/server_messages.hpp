#pragma once
// Server -> client messages: the authoritative state and what happened. Times named *_ms are the
// server's clock in milliseconds; every message with a deadline also carries server_time_ms so a
// client with a skewed clock counts down by the difference. Match times t_s are seconds since the
// start of the current shot.

#include "carrom/config.hpp"
#include "carrom/proto/error.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/proto/version.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::proto {

// "welcome": the answer to hello.
struct Welcome {
    int version = kProtocolVersion;  // "version"
    std::int64_t player_id = 0;      // "player_id", 0..kMaxNonce, unique per server run
    std::string resume_token;        // "resume_token", 32 lowercase hex
    std::int64_t server_time_ms = 0; // "server_time_ms"
    friend bool operator==(const Welcome&, const Welcome&) = default;
};

struct SeatInfo {
    bool occupied = false;                // "occupied": someone (or a bot) holds the seat
    std::string name;                     // "name", empty when not occupied
    bool connected = false;               // "connected": false while a dropped player has grace
    bool bot = false;                     // "bot": a server-side bot
    Colour colour = Colour::None;         // "colour": the coins the seat plays (none in freestyle)
    Baseline baseline = Baseline::Bottom; // "baseline": "bottom", "right", "top" or "left"
    int team = 0; // "team": singles: the seat; doubles: seat % 2 (absent on the wire: the seat)
    friend bool operator==(const SeatInfo&, const SeatInfo&) = default;
};

struct MatchOptions {          // options with every default resolved
    int target_points = 25;    // "target_points"
    int boards = 8;            // "boards"
    double shot_clock_s = 0.0; // "shot_clock_s", 0 = off
    friend bool operator==(const MatchOptions&, const MatchOptions&) = default;
};

// "room_state": everything a client needs to draw the room; sent on join, rejoin, seat changes
// and after every shot.
// How the pieces move between snapshots: every body follows the damped free motion
// p(t) = p0 + v0 (1 - e^(-k t)) / k between changes of motion, and with contact_snapshots the
// server sends a delta at the instant of every change (contact, stop, pocketing), so a client
// can draw from the newest state forward exactly until the next one arrives.
struct MotionInfo {
    double damping_per_s = PhysicsConfig{}.damping_per_s; // "damping_per_s": k, 1/s
    bool contact_snapshots = false;                       // "contact_snapshots"
    friend bool operator==(const MotionInfo&, const MotionInfo&) = default;
};

struct RoomState {
    std::string code;                // "code"
    int you = -1;                    // "you": the receiver's seat, -1 for a spectator
    RuleSet rule_set = RuleSet::Icf; // "rule_set"
    MatchOptions options;            // "options"
    std::vector<SeatInfo> seats;     // "seats", 2..kMaxSeats
    int spectators = 0;              // "spectators"
    std::vector<int> scores;         // "scores", one per seat: its team's (partners share one)
    std::vector<int> dues;           // "dues": dues owed, one per seat: its team's
    int board_number = 1;            // "board_number", 1-based
    int turn = 0;                    // "turn": the number the next game input must carry
    int to_play = 0;                 // "to_play": seat to shoot
    std::optional<std::int64_t> shot_clock_deadline_ms; // "shot_clock_deadline_ms", absent: none
    std::int64_t server_time_ms = 0;                    // "server_time_ms"
    Phase phase = Phase::Waiting;                       // "phase"
    QueenInfo queen;                                    // "queen": {"state", "seat"}
    int winner = -1;               // "winner": the winning team (= its first seat), -1 while none
    std::vector<BoardBody> bodies; // "bodies": the full board, every body with its kind
    MotionInfo motion;             // "motion", optional on the wire (absent: the defaults above)
    // "aim_assist": the room allows the aim guide to the first piece the striker would touch
    // (practice, bot and other unrated games; off in rated ones). Optional on the wire (absent:
    // true).
    bool aim_assist = true;
    friend bool operator==(const RoomState&, const RoomState&) = default;
};

// One moved body in a snapshot. On the wire: [id, x, y, vx, vy].
struct SnapshotBody {
    int id = 0;
    Vec2 pos_px{};
    Vec2 vel_px_s{};
    friend bool operator==(const SnapshotBody&, const SnapshotBody&) = default;
};

// "snapshot": while a shot plays, at the snapshot rate. A delta lists the bodies whose position
// or velocity changed since the previous snapshot (seq - 1) and the bodies pocketed since then.
// A keyframe lists every body on the board in "bodies" and every pocketed body in "pocketed";
// it replaces the receiver's state (sent on join, on rejoin, at the end of every shot and after
// a slow client's dropped snapshots).
struct Snapshot {
    std::int64_t seq = 0;             // "seq": per room, +1 per broadcast snapshot
    int turn = 0;                     // "turn": the shot's turn number
    double t_s = 0.0;                 // "t": seconds since the shot started
    bool keyframe = false;            // "keyframe"
    std::vector<SnapshotBody> bodies; // "bodies": [[id, x, y, vx, vy], ...]
    std::vector<int> pocketed;        // "pocketed": [id, ...]
    // "due_ms"?: the server-clock time (ms) this snapshot was due by the room's snapshot
    // schedule (deltas while a shot plays; absent in keyframes). A client on the server's host
    // (the load tool) compares it with its own monotonic clock to measure lateness.
    std::optional<std::int64_t> due_ms;
    friend bool operator==(const Snapshot&, const Snapshot&) = default;
};

// Event payloads. Physics events carry the shot's turn and time t_s (for sound and timing).
struct CollisionEvent { // "collision": bodies a and b exchanged `impulse` (mass * px/s)
    int turn = 0;
    double t_s = 0.0;
    int a = 0;
    int b = 0;
    double impulse = 0.0;
    friend bool operator==(const CollisionEvent&, const CollisionEvent&) = default;
};
struct CushionEvent { // "cushion": body hit cushion 0 left, 1 right, 2 top, 3 bottom
    int turn = 0;
    double t_s = 0.0;
    int body = 0;
    int cushion = 0;
    double impulse = 0.0;
    friend bool operator==(const CushionEvent&, const CushionEvent&) = default;
};
struct PocketEvent { // "pocket": body entered pocket 0 top-left, 1 top-right, 2 bottom-left, 3
                     // bottom-right
    int turn = 0;
    double t_s = 0.0;
    int body = 0;
    int pocket = 0;
    friend bool operator==(const PocketEvent&, const PocketEvent&) = default;
};
struct FoulEvent { // "foul": the rules' foul code and a sentence
    int seat = 0;
    std::string rule;
    std::string message;
    friend bool operator==(const FoulEvent&, const FoulEvent&) = default;
};
struct QueenEvent { // "queen": the queen's new state
    QueenInfo queen;
    friend bool operator==(const QueenEvent&, const QueenEvent&) = default;
};
struct DueEvent { // "due": seat now owes `owed` dues
    int seat = 0;
    int owed = 0;
    friend bool operator==(const DueEvent&, const DueEvent&) = default;
};
struct TurnEvent { // "turn": seat to play turn number `turn`, with the shot clock
    int turn = 0;
    int seat = 0;
    std::optional<std::int64_t> deadline_ms; // absent: no shot clock
    std::int64_t server_time_ms = 0;
    friend bool operator==(const TurnEvent&, const TurnEvent&) = default;
};
struct BoardEndEvent { // "board_end": board `board` won by team `winner` (-1: none) for `points`
    int board = 1;
    int winner = -1;
    int points = 0;
    std::vector<int> scores;
    friend bool operator==(const BoardEndEvent&, const BoardEndEvent&) = default;
};
struct GameEndEvent { // "game_end"; reason: "score", "boards", "cleared", "forfeit", "left",
                      // "clock"
    int winner = -1;
    std::string reason;
    std::vector<int> scores;
    // "rule"?: the rules engine's code of the end ("target_points", "boards_played",
    // "board_cleared", ...), the name the journal and the Match API give it; empty when absent.
    std::string rule{};
    friend bool operator==(const GameEndEvent&, const GameEndEvent&) = default;
};
struct PlayerDroppedEvent { // "player_dropped": the seat forfeits at grace_deadline_ms unless it
                            // resumes
    int seat = 0;
    std::int64_t grace_deadline_ms = 0;
    std::int64_t server_time_ms = 0;
    friend bool operator==(const PlayerDroppedEvent&, const PlayerDroppedEvent&) = default;
};
struct PlayerReturnedEvent { // "player_returned"
    int seat = 0;
    friend bool operator==(const PlayerReturnedEvent&, const PlayerReturnedEvent&) = default;
};
struct AimEvent { // "aim": the shooter's striker position while aiming
    int seat = 0;
    int turn = 0;
    double x_px = 0.0;
    friend bool operator==(const AimEvent&, const AimEvent&) = default;
};

struct EmoteEvent { // "emote": seat `seat` sent the quick reaction `emote` (not journaled)
    int seat = 0;
    Emote emote = Emote::NiceShot;
    friend bool operator==(const EmoteEvent&, const EmoteEvent&) = default;
};

// "paused": the match waits: the server cannot commit its latest stroke (the match store does not
// answer) and streams nothing of it until it can (docs/cluster.md, "The database down").
struct PausedEvent {
    std::string reason;  // "reason": "store"
    std::string message; // "message": a sentence for the players
    friend bool operator==(const PausedEvent&, const PausedEvent&) = default;
};
struct ResumedEvent { // "resumed": the wait of `paused` is over; the stroke streams now
    friend bool operator==(const ResumedEvent&, const ResumedEvent&) = default;
};

// "event": {"type": "event", "kind": <name above>, ...payload fields}.
using Event = std::variant<CollisionEvent, CushionEvent, PocketEvent, FoulEvent, QueenEvent,
                           DueEvent, TurnEvent, BoardEndEvent, GameEndEvent, PlayerDroppedEvent,
                           PlayerReturnedEvent, AimEvent, EmoteEvent, PausedEvent, ResumedEvent>;
std::string_view event_kind(const Event& event);

struct Foul {
    std::string rule;    // "rule": stable code from the rules engine
    std::string message; // "message"
    friend bool operator==(const Foul&, const Foul&) = default;
};

// "shot_result": the rules' outcome of turn `turn`, after the shot's final keyframe.
struct ShotResult {
    int turn = 0;      // "turn": the turn that was played
    int seat = 0;      // "seat": the shooter
    double x_px = 0.0; // "x", "angle", "power": the shot as played
    double angle_rad = 0.0;
    double power = 0.0;
    std::vector<int> pocketed; // "pocketed": ids pocketed by this shot (striker included)
    std::vector<int> returned; // "returned": ids put back on the board by the rules
    std::vector<Foul> fouls;   // "fouls"
    std::vector<int> points;   // "points": score change per seat (its team's)
    std::vector<int> scores;   // "scores": scores after the shot
    std::vector<int> dues;     // "dues": dues owed per seat after the shot
    QueenInfo queen;           // "queen"
    bool extra_turn = false;   // "extra_turn": the shooter plays again
    int next_turn = 0;         // "next_turn"
    int next_seat = 0;         // "next_seat"
    bool board_over = false;   // "board_over"
    bool game_over = false;    // "game_over"
    int winner = -1;           // "winner": team of the game when game_over, else -1
    friend bool operator==(const ShotResult&, const ShotResult&) = default;
};

// "error" is proto::Error: {"type": "error", "code", "message"}.

// "pong": the answer to ping.
struct Pong {
    std::int64_t nonce = 0;
    std::int64_t server_time_ms = 0;
    friend bool operator==(const Pong&, const Pong&) = default;
};

// "redirect": the room or seat the client asked for is run by another instance of the cluster
// (docs/cluster.md, "Redirects"); sent only to a client whose hello had follows_redirects. The
// server closes the connection after it (close 4005). The client connects to `url`, says hello
// (with its resume token when it holds a seat) and, when `code` is set and it holds no seat
// there, joins that room `as`.
struct Redirect {
    std::string url;        // "url": ws:// or wss://, at most kMaxUrlBytes
    std::string reason;     // "reason": "room", "seat", "quick_match" or "moved"
    std::string code;       // "code"?: the room to join there; empty when absent
    Role as = Role::Player; // "as"?: with code: player (default) or spectator
    friend bool operator==(const Redirect&, const Redirect&) = default;
};

using ServerMessage =
    std::variant<Welcome, RoomState, Snapshot, Event, ShotResult, Error, Pong, Redirect>;

std::string_view type_name(const ServerMessage& message);

} // namespace carrom::proto
