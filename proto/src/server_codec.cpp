// JSON encoding and validating decoding of server -> client messages. Clients decode with the
// same care as the server: a broken or hostile server must not crash them.
#include "carrom/proto/json_codec.hpp"

#include "json_reader.hpp"
#include "message_names.hpp"

namespace carrom::proto {

using detail::JsonReader;
using detail::Range;
using nlohmann::json;

namespace {

constexpr int kMaxId = 1000000;
constexpr int kMaxMessageScore = 100000;
constexpr int kMaxSeatIndex = static_cast<int>(kMaxSeats) - 1;

json encode_queen(const QueenInfo& q) {
    return json{{"state", to_string(q.state)}, {"seat", q.seat}};
}

void decode_queen(JsonReader& parent, std::string_view key, QueenInfo& q) {
    const json* value = parent.object(key);
    if (value == nullptr) {
        return;
    }
    JsonReader r = parent.nested(*value, parent.path_of(key));
    q.state = r.enumeration("state", kQueenStateNames, QueenState::OnBoard);
    q.seat = r.small_int("seat", -1, kMaxSeatIndex);
    parent.merge(r.error());
}

void decode_optional_time(JsonReader& r, std::string_view key, std::optional<std::int64_t>& out) {
    if (r.has(key)) {
        out = r.integer(key, 0, kMaxTimeMs);
    }
}

// --- welcome ---
json encode_body(const Welcome& m) {
    return json{{"version", m.version},
                {"player_id", m.player_id},
                {"resume_token", m.resume_token},
                {"server_time_ms", m.server_time_ms}};
}
void decode_body(JsonReader& r, Welcome& m) {
    m.version = r.small_int("version", 0, 1000000);
    m.player_id = r.integer("player_id", 0, kMaxNonce);
    m.resume_token = r.text("resume_token", kResumeTokenLength, kResumeTokenLength);
    if (r.ok() && !is_resume_token(m.resume_token)) {
        r.fail("resume_token", "must be 32 lowercase hexadecimal digits");
    }
    m.server_time_ms = r.integer("server_time_ms", 0, kMaxTimeMs);
}

// --- room_state ---
json encode_seat(const SeatInfo& s) {
    return json{{"occupied", s.occupied},
                {"name", s.name},
                {"connected", s.connected},
                {"bot", s.bot},
                {"colour", to_string(s.colour)},
                {"baseline", baseline_name(s.baseline)},
                {"team", s.team}};
}
void decode_seat(JsonReader& r, SeatInfo& s) {
    s.occupied = r.boolean("occupied");
    s.name = r.text("name", 0, kMaxNameBytes);
    s.connected = r.boolean("connected");
    s.bot = r.boolean("bot");
    s.colour = r.enumeration("colour", kColourNames, Colour::None);
    s.baseline = r.enumeration("baseline", rules::kSideNames, Baseline::Bottom);
    // Absent (a server before doubles): -1 here, the seat's index once the array is read.
    s.team = r.has("team") ? r.small_int("team", 0, kMaxSeatIndex) : -1;
}

json encode_board_body(const BoardBody& b) {
    return json{{"id", b.id},
                {"kind", body_kind_name(b.kind)},
                {"x", b.pos_px.x},
                {"y", b.pos_px.y},
                {"vx", b.vel_px_s.x},
                {"vy", b.vel_px_s.y},
                {"pocketed", b.pocketed}};
}
void decode_board_body(JsonReader& r, BoardBody& b) {
    b.id = r.small_int("id", 0, kMaxId);
    b.kind = r.enumeration("kind", kBodyKindNames, BodyKind::Black);
    b.pos_px.x = r.number("x", {-kMaxCoordinatePx, kMaxCoordinatePx});
    b.pos_px.y = r.number("y", {-kMaxCoordinatePx, kMaxCoordinatePx});
    b.vel_px_s.x = r.number("vx", {-kMaxSpeedPxS, kMaxSpeedPxS});
    b.vel_px_s.y = r.number("vy", {-kMaxSpeedPxS, kMaxSpeedPxS});
    b.pocketed = r.boolean("pocketed");
}

// Reads an array of objects with `decode_item` into `out`.
template <class T, class F>
void decode_object_array(JsonReader& r, std::string_view key, std::size_t max_items,
                         std::vector<T>& out, F decode_item) {
    const json* items = r.array(key, max_items);
    if (items == nullptr) {
        return;
    }
    for (std::size_t i = 0; i < items->size() && r.ok(); ++i) {
        const json& item = (*items)[i];
        const std::string path = detail::index_path(r.path_of(key), i);
        if (!item.is_object()) {
            r.fail_at(path, "must be an object");
            return;
        }
        JsonReader child = r.nested(item, path);
        T value;
        decode_item(child, value);
        r.merge(child.error());
        out.push_back(std::move(value));
    }
}

json encode_body(const RoomState& m) {
    json seats = json::array();
    for (const auto& s : m.seats) {
        seats.push_back(encode_seat(s));
    }
    json bodies = json::array();
    for (const auto& b : m.bodies) {
        bodies.push_back(encode_board_body(b));
    }
    json out{{"code", m.code},
             {"you", m.you},
             {"rule_set", to_string(m.rule_set)},
             {"options",
              {{"target_points", m.options.target_points},
               {"boards", m.options.boards},
               {"shot_clock_s", m.options.shot_clock_s}}},
             {"seats", std::move(seats)},
             {"spectators", m.spectators},
             {"scores", m.scores},
             {"dues", m.dues},
             {"board_number", m.board_number},
             {"turn", m.turn},
             {"to_play", m.to_play},
             {"server_time_ms", m.server_time_ms},
             {"phase", to_string(m.phase)},
             {"queen", encode_queen(m.queen)},
             {"winner", m.winner},
             {"bodies", std::move(bodies)},
             {"motion",
              {{"damping_per_s", m.motion.damping_per_s},
               {"contact_snapshots", m.motion.contact_snapshots}}},
             {"aim_assist", m.aim_assist}};
    if (m.shot_clock_deadline_ms) {
        out["shot_clock_deadline_ms"] = *m.shot_clock_deadline_ms;
    }
    return out;
}
void decode_body(JsonReader& r, RoomState& m) {
    m.code = r.text("code", kRoomCodeLength, kRoomCodeLength);
    if (r.ok() && !is_room_code(m.code)) {
        r.fail("code", "must be a room code");
    }
    m.you = r.small_int("you", -1, kMaxSeatIndex);
    m.rule_set = r.enumeration("rule_set", kRuleSetNames, RuleSet::Icf);
    if (const json* options = r.object("options")) {
        JsonReader o = r.nested(*options, r.path_of("options"));
        m.options.target_points = o.small_int("target_points", 1, kMaxTargetPoints);
        m.options.boards = o.small_int("boards", 1, kMaxBoards);
        m.options.shot_clock_s = o.number("shot_clock_s", {0.0, kMaxShotClockS});
        r.merge(o.error());
    }
    decode_object_array(r, "seats", kMaxSeats, m.seats, decode_seat);
    if (r.ok() && m.seats.size() != 2 && m.seats.size() != 4) {
        r.fail("seats", "must have 2 or 4 items");
    }
    for (std::size_t i = 0; i < m.seats.size(); ++i) {
        if (m.seats[i].team < 0) {
            m.seats[i].team = static_cast<int>(i);
        }
    }
    m.spectators = r.small_int("spectators", 0, 1000000);
    m.scores = r.int_array("scores", -kMaxMessageScore, kMaxMessageScore, kMaxSeats);
    m.dues = r.int_array("dues", 0, kMaxMessageScore, kMaxSeats);
    if (r.ok() && (m.scores.size() != m.seats.size() || m.dues.size() != m.seats.size())) {
        r.fail("scores", "and 'dues' must have one item per seat");
    }
    m.board_number = r.small_int("board_number", 1, 1000);
    m.turn = static_cast<int>(r.integer("turn", 0, kMaxTurn));
    m.to_play = r.small_int("to_play", 0, kMaxSeatIndex);
    decode_optional_time(r, "shot_clock_deadline_ms", m.shot_clock_deadline_ms);
    m.server_time_ms = r.integer("server_time_ms", 0, kMaxTimeMs);
    m.phase = r.enumeration("phase", kPhaseNames, Phase::Waiting);
    decode_queen(r, "queen", m.queen);
    m.winner = r.small_int("winner", -1, kMaxSeatIndex);
    decode_object_array(r, "bodies", kMaxBodies, m.bodies, decode_board_body);
    if (r.has("motion")) {
        if (const json* motion = r.object("motion")) {
            JsonReader o = r.nested(*motion, r.path_of("motion"));
            m.motion.damping_per_s = o.number("damping_per_s", {0.0, 100.0});
            m.motion.contact_snapshots = o.boolean("contact_snapshots");
            r.merge(o.error());
        }
    }
    if (r.has("aim_assist")) {
        m.aim_assist = r.boolean("aim_assist");
    }
}

// --- snapshot ---
json encode_body(const Snapshot& m) {
    json bodies = json::array();
    for (const auto& b : m.bodies) {
        bodies.push_back(json::array({b.id, b.pos_px.x, b.pos_px.y, b.vel_px_s.x, b.vel_px_s.y}));
    }
    json out{{"seq", m.seq},
             {"turn", m.turn},
             {"t", m.t_s},
             {"keyframe", m.keyframe},
             {"bodies", std::move(bodies)},
             {"pocketed", m.pocketed}};
    if (m.due_ms) {
        out["due_ms"] = *m.due_ms;
    }
    return out;
}
bool decode_snapshot_body(const json& item, SnapshotBody& b) {
    if (!item.is_array() || item.size() != 5) {
        return false;
    }
    std::int64_t id = 0;
    return detail::read_integer(item[0], 0, kMaxId, id) &&
           detail::read_number(item[1], -kMaxCoordinatePx, kMaxCoordinatePx, b.pos_px.x) &&
           detail::read_number(item[2], -kMaxCoordinatePx, kMaxCoordinatePx, b.pos_px.y) &&
           detail::read_number(item[3], -kMaxSpeedPxS, kMaxSpeedPxS, b.vel_px_s.x) &&
           detail::read_number(item[4], -kMaxSpeedPxS, kMaxSpeedPxS, b.vel_px_s.y) &&
           (b.id = static_cast<int>(id), true);
}
void decode_body(JsonReader& r, Snapshot& m) {
    m.seq = r.integer("seq", 0, kMaxNonce);
    m.turn = static_cast<int>(r.integer("turn", 0, kMaxTurn));
    m.t_s = r.number("t", {0.0, kMaxMatchTimeS});
    m.keyframe = r.boolean("keyframe");
    if (const json* bodies = r.array("bodies", kMaxBodies)) {
        for (const json& item : *bodies) {
            SnapshotBody b;
            if (!decode_snapshot_body(item, b)) {
                r.fail("bodies", "must hold [id, x, y, vx, vy] arrays of finite numbers in range");
                break;
            }
            m.bodies.push_back(b);
        }
    }
    m.pocketed = r.int_array("pocketed", 0, kMaxId, kMaxBodies);
    decode_optional_time(r, "due_ms", m.due_ms);
}

// --- events ---
json encode_event(const CollisionEvent& e) {
    return json{{"turn", e.turn}, {"t", e.t_s}, {"a", e.a}, {"b", e.b}, {"impulse", e.impulse}};
}
json encode_event(const CushionEvent& e) {
    return json{{"turn", e.turn},
                {"t", e.t_s},
                {"body", e.body},
                {"cushion", e.cushion},
                {"impulse", e.impulse}};
}
json encode_event(const PocketEvent& e) {
    return json{{"turn", e.turn}, {"t", e.t_s}, {"body", e.body}, {"pocket", e.pocket}};
}
json encode_event(const FoulEvent& e) {
    return json{{"seat", e.seat}, {"rule", e.rule}, {"message", e.message}};
}
json encode_event(const QueenEvent& e) {
    return json{{"queen", encode_queen(e.queen)}};
}
json encode_event(const DueEvent& e) {
    return json{{"seat", e.seat}, {"owed", e.owed}};
}
json encode_event(const TurnEvent& e) {
    json out{{"turn", e.turn}, {"seat", e.seat}, {"server_time_ms", e.server_time_ms}};
    if (e.deadline_ms) {
        out["deadline_ms"] = *e.deadline_ms;
    }
    return out;
}
json encode_event(const BoardEndEvent& e) {
    return json{
        {"board", e.board}, {"winner", e.winner}, {"points", e.points}, {"scores", e.scores}};
}
json encode_event(const GameEndEvent& e) {
    json out{{"winner", e.winner}, {"reason", e.reason}, {"scores", e.scores}};
    if (!e.rule.empty()) {
        out["rule"] = e.rule;
    }
    return out;
}
json encode_event(const PlayerDroppedEvent& e) {
    return json{{"seat", e.seat},
                {"grace_deadline_ms", e.grace_deadline_ms},
                {"server_time_ms", e.server_time_ms}};
}
json encode_event(const PlayerReturnedEvent& e) {
    return json{{"seat", e.seat}};
}
json encode_event(const AimEvent& e) {
    return json{{"seat", e.seat}, {"turn", e.turn}, {"x", e.x_px}};
}
json encode_event(const EmoteEvent& e) {
    return json{{"seat", e.seat}, {"emote", to_string(e.emote)}};
}
json encode_event(const PausedEvent& e) {
    return json{{"reason", e.reason}, {"message", e.message}};
}
json encode_event(const ResumedEvent&) {
    return json::object();
}

int read_turn(JsonReader& r) {
    return static_cast<int>(r.integer("turn", 0, kMaxTurn));
}
double read_time(JsonReader& r) {
    return r.number("t", {0.0, kMaxMatchTimeS});
}
int read_seat(JsonReader& r, std::string_view key) {
    return r.small_int(key, 0, kMaxSeatIndex);
}

void decode_event(JsonReader& r, CollisionEvent& e) {
    e.turn = read_turn(r);
    e.t_s = read_time(r);
    e.a = r.small_int("a", 0, kMaxId);
    e.b = r.small_int("b", 0, kMaxId);
    e.impulse = r.number("impulse", {0.0, kMaxImpulse});
}
void decode_event(JsonReader& r, CushionEvent& e) {
    e.turn = read_turn(r);
    e.t_s = read_time(r);
    e.body = r.small_int("body", 0, kMaxId);
    e.cushion = r.small_int("cushion", 0, 3);
    e.impulse = r.number("impulse", {0.0, kMaxImpulse});
}
void decode_event(JsonReader& r, PocketEvent& e) {
    e.turn = read_turn(r);
    e.t_s = read_time(r);
    e.body = r.small_int("body", 0, kMaxId);
    e.pocket = r.small_int("pocket", 0, 3);
}
void decode_event(JsonReader& r, FoulEvent& e) {
    e.seat = read_seat(r, "seat");
    e.rule = r.text("rule", 1, kMaxTextBytes);
    e.message = r.text("message", 0, kMaxTextBytes);
}
void decode_event(JsonReader& r, QueenEvent& e) {
    decode_queen(r, "queen", e.queen);
}
void decode_event(JsonReader& r, DueEvent& e) {
    e.seat = read_seat(r, "seat");
    e.owed = r.small_int("owed", 0, kMaxMessageScore);
}
void decode_event(JsonReader& r, TurnEvent& e) {
    e.turn = read_turn(r);
    e.seat = read_seat(r, "seat");
    decode_optional_time(r, "deadline_ms", e.deadline_ms);
    e.server_time_ms = r.integer("server_time_ms", 0, kMaxTimeMs);
}
void decode_event(JsonReader& r, BoardEndEvent& e) {
    e.board = r.small_int("board", 1, 1000);
    e.winner = r.small_int("winner", -1, kMaxSeatIndex);
    e.points = r.small_int("points", -kMaxMessageScore, kMaxMessageScore);
    e.scores = r.int_array("scores", -kMaxMessageScore, kMaxMessageScore, kMaxSeats);
}
void decode_event(JsonReader& r, GameEndEvent& e) {
    e.winner = r.small_int("winner", -1, kMaxSeatIndex);
    e.reason = r.text("reason", 1, 32);
    e.scores = r.int_array("scores", -kMaxMessageScore, kMaxMessageScore, kMaxSeats);
    if (r.has("rule")) {
        e.rule = r.text("rule", 1, 32);
    }
}
void decode_event(JsonReader& r, PlayerDroppedEvent& e) {
    e.seat = read_seat(r, "seat");
    e.grace_deadline_ms = r.integer("grace_deadline_ms", 0, kMaxTimeMs);
    e.server_time_ms = r.integer("server_time_ms", 0, kMaxTimeMs);
}
void decode_event(JsonReader& r, PlayerReturnedEvent& e) {
    e.seat = read_seat(r, "seat");
}
void decode_event(JsonReader& r, AimEvent& e) {
    e.seat = read_seat(r, "seat");
    e.turn = read_turn(r);
    e.x_px = r.number("x", {0.0, kMaxCoordinatePx});
}
void decode_event(JsonReader& r, EmoteEvent& e) {
    e.seat = read_seat(r, "seat");
    e.emote = r.enumeration("emote", kEmoteNames, Emote::NiceShot);
}
void decode_event(JsonReader& r, PausedEvent& e) {
    e.reason = r.text("reason", 1, 32);
    e.message = r.text("message", 0, kMaxTextBytes);
}
void decode_event(JsonReader&, ResumedEvent&) {}

json encode_body(const Event& m) {
    json out = std::visit([](const auto& e) { return encode_event(e); }, m);
    out["kind"] = event_kind(m);
    return out;
}
void decode_body(JsonReader& r, Event& m) {
    const std::string kind = r.text("kind", 1, 32);
    if (!r.ok()) {
        return;
    }
    const auto index = detail::find_type(detail::kEventKindNames, kind);
    if (!index) {
        r.fail("kind", "must name a known event kind");
        return;
    }
    if (auto event =
            detail::make_alternative<Event>(*index, [&r](auto& e) { decode_event(r, e); })) {
        m = std::move(*event);
    }
}

// --- shot_result ---
json encode_body(const ShotResult& m) {
    json fouls = json::array();
    for (const auto& f : m.fouls) {
        fouls.push_back(json{{"rule", f.rule}, {"message", f.message}});
    }
    return json{{"turn", m.turn},
                {"seat", m.seat},
                {"x", m.x_px},
                {"angle", m.angle_rad},
                {"power", m.power},
                {"pocketed", m.pocketed},
                {"returned", m.returned},
                {"fouls", std::move(fouls)},
                {"points", m.points},
                {"scores", m.scores},
                {"dues", m.dues},
                {"queen", encode_queen(m.queen)},
                {"extra_turn", m.extra_turn},
                {"next_turn", m.next_turn},
                {"next_seat", m.next_seat},
                {"board_over", m.board_over},
                {"game_over", m.game_over},
                {"winner", m.winner}};
}
void decode_foul(JsonReader& r, Foul& f) {
    f.rule = r.text("rule", 1, kMaxTextBytes);
    f.message = r.text("message", 0, kMaxTextBytes);
}
void decode_body(JsonReader& r, ShotResult& m) {
    m.turn = read_turn(r);
    m.seat = read_seat(r, "seat");
    m.x_px = r.number("x", {0.0, kMaxCoordinatePx});
    m.angle_rad = r.number("angle", {-kMaxAngleRad, kMaxAngleRad});
    m.power = r.number("power", {0.0, kMaxPower});
    m.pocketed = r.int_array("pocketed", 0, kMaxId, kMaxBodies);
    m.returned = r.int_array("returned", 0, kMaxId, kMaxBodies);
    decode_object_array(r, "fouls", 16, m.fouls, decode_foul);
    m.points = r.int_array("points", -kMaxMessageScore, kMaxMessageScore, kMaxSeats);
    m.scores = r.int_array("scores", -kMaxMessageScore, kMaxMessageScore, kMaxSeats);
    m.dues = r.int_array("dues", 0, kMaxMessageScore, kMaxSeats);
    decode_queen(r, "queen", m.queen);
    m.extra_turn = r.boolean("extra_turn");
    m.next_turn = static_cast<int>(r.integer("next_turn", 0, kMaxTurn));
    m.next_seat = read_seat(r, "next_seat");
    m.board_over = r.boolean("board_over");
    m.game_over = r.boolean("game_over");
    m.winner = r.small_int("winner", -1, kMaxSeatIndex);
}

// --- error, pong ---
json encode_body(const Error& m) {
    return json{{"code", m.code}, {"message", m.message}};
}
void decode_body(JsonReader& r, Error& m) {
    m.code = r.text("code", 1, 64);
    m.message = r.text("message", 0, kMaxTextBytes);
}
json encode_body(const Pong& m) {
    return json{{"nonce", m.nonce}, {"server_time_ms", m.server_time_ms}};
}
void decode_body(JsonReader& r, Pong& m) {
    m.nonce = r.integer("nonce", 0, kMaxNonce);
    m.server_time_ms = r.integer("server_time_ms", 0, kMaxTimeMs);
}

// --- redirect ---
json encode_body(const Redirect& m) {
    json out{{"url", m.url}, {"reason", m.reason}};
    if (!m.code.empty()) {
        out["code"] = m.code;
        out["as"] = to_string(m.as);
    }
    return out;
}
void decode_body(JsonReader& r, Redirect& m) {
    m.url = r.text("url", 6, kMaxUrlBytes);
    if (r.ok() && m.url.rfind("ws://", 0) != 0 && m.url.rfind("wss://", 0) != 0) {
        r.fail("url", "must be a ws:// or wss:// URL");
    }
    m.reason = r.text("reason", 1, 32);
    if (r.has("code")) {
        m.code = r.text("code", kRoomCodeLength, kRoomCodeLength);
        if (r.ok() && !is_room_code(m.code)) {
            r.fail("code", "must be 6 characters from " + std::string(kRoomCodeAlphabet));
        }
        if (r.has("as")) {
            m.as = r.enumeration("as", kRoleNames, Role::Player);
        }
    }
}

} // namespace

std::string_view type_name(const ServerMessage& message) {
    return detail::kServerTypeNames[message.index()];
}

std::string_view event_kind(const Event& event) {
    return detail::kEventKindNames[event.index()];
}

json to_json(const ServerMessage& message) {
    return detail::encode_message(message, detail::kServerTypeNames,
                                  [](const auto& m) { return encode_body(m); });
}

DecodedMessage<ServerMessage> server_from_json(const json& value) {
    return detail::decode_message<ServerMessage>(
        value, detail::kServerTypeNames, [](JsonReader& r, auto& body) { decode_body(r, body); });
}

} // namespace carrom::proto
