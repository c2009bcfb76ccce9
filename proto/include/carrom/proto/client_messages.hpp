#pragma once
// Client -> server messages: intentions only. Field comments give wire names and ranges.

#include "carrom/proto/types.hpp"
#include "carrom/proto/version.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::proto {

// "hello": the first message on every connection.
struct Hello {
    int version = kProtocolVersion;          // "version", integer
    std::string name;                        // "name", see is_player_name
    std::optional<std::string> resume_token; // "resume_token", 32 lowercase hex; reclaims a seat
    // "identity", optional: the player's key, 1..kMaxIdentityBytes characters on the wire; the
    // server accepts only is_identity_key (64 lowercase hex, 256 bits) and refuses anything else
    // with bad_identity. Absent: a guest (docs/ratings.md, "Identity").
    std::optional<std::string> identity = {};
    // "follows_redirects", optional (default false; sent only when true): the client follows a
    // `redirect` to another instance of a cluster (docs/cluster.md). Without it the server
    // answers a room or seat run by another instance with an error naming that instance's URL.
    bool follows_redirects = false;
    friend bool operator==(const Hello&, const Hello&) = default;
};

// Match options; each absent one takes the rule set's default.
struct RoomOptions {
    std::optional<int> target_points;   // "target_points", 1..kMaxTargetPoints
    std::optional<int> boards;          // "boards", 1..kMaxBoards
    std::optional<double> shot_clock_s; // "shot_clock_s", 0 (off) or (0, kMaxShotClockS]
    friend bool operator==(const RoomOptions&, const RoomOptions&) = default;
};

struct BotSeat {
    BotLevel level = BotLevel::Medium; // "level"
    // "seats", optional: the seats the server's bots take, distinct, in 1..seats-1, at least one.
    // Empty (absent on the wire): every seat but the creator's.
    std::vector<int> seats{};
    friend bool operator==(const BotSeat&, const BotSeat&) = default;
};

// "create_room": a private room; the creator takes seat 0. With "bot", server bots take the bot
// seats (singles: seat 1).
struct CreateRoom {
    RuleSet rule_set = RuleSet::Icf; // "rule_set", optional on the wire (default icf)
    RoomOptions options;             // "options", optional object
    std::optional<BotSeat> bot;      // "bot", optional object
    int seats = 2;                   // "seats", optional: 2 (singles, default) or 4 (doubles)
    bool rated = false; // "rated", optional boolean: a rated room (singles, identified players,
                        // no bot); on the wire only when true
    friend bool operator==(const CreateRoom&, const CreateRoom&) = default;
};

// "join_room": by code, as a player (a free seat) or as a spectator.
struct JoinRoom {
    std::string code;       // "code", see is_room_code
    Role as = Role::Player; // "as", optional (default player)
    friend bool operator==(const JoinRoom&, const JoinRoom&) = default;
};

// "quick_match": wait to be paired with other waiting players of the same rule set and seat count.
struct QuickMatch {
    RuleSet rule_set = RuleSet::Icf; // "rule_set", optional (default icf)
    int seats = 2;                   // "seats", optional: 2 (singles, default) or 4 (doubles)
    friend bool operator==(const QuickMatch&, const QuickMatch&) = default;
};

// "aim": striker position while aiming, relayed to the room as an "aim" event.
struct Aim {
    int turn = 0;      // "turn", 0..kMaxTurn: the turn this input was made for
    double x_px = 0.0; // "x", striker centre on the baseline, [0, kMaxCoordinatePx]
    friend bool operator==(const Aim&, const Aim&) = default;
};

// "shoot": play the turn. Placement and power are checked against the rules by the server.
struct Shoot {
    int turn = 0;           // "turn", 0..kMaxTurn
    double x_px = 0.0;      // "x", [0, kMaxCoordinatePx]
    double angle_rad = 0.0; // "angle", [-kMaxAngleRad, kMaxAngleRad]; 0 = +x, pi/2 = +y (down)
    double power = 0.0;     // "power", [0, kMaxPower]; the rules allow [0, max_power = 25]
    friend bool operator==(const Shoot&, const Shoot&) = default;
};

struct Rematch { // "rematch": after game over; a new game starts when every human seat asks
    friend bool operator==(const Rematch&, const Rematch&) = default;
};
struct Leave { // "leave": give up the seat (forfeit if a game is running) or stop spectating
    friend bool operator==(const Leave&, const Leave&) = default;
};
// "emote": a quick reaction from a seated player, shown beside the seat in every client. The room
// limits each seat's rate (docs/protocol.md: emote_too_fast).
struct EmoteMessage {
    Emote emote = Emote::NiceShot; // "emote", a name of kEmoteNames
    friend bool operator==(const EmoteMessage&, const EmoteMessage&) = default;
};
struct Ping {
    std::int64_t nonce = 0; // "nonce", 0..kMaxNonce, echoed in pong
    friend bool operator==(const Ping&, const Ping&) = default;
};

using ClientMessage = std::variant<Hello, CreateRoom, JoinRoom, QuickMatch, Aim, Shoot, Rematch,
                                   Leave, Ping, EmoteMessage>;

// The wire "type" of a message, e.g. "hello".
std::string_view type_name(const ClientMessage& message);

} // namespace carrom::proto
