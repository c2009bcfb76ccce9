// JSON encoding and validating decoding of client -> server messages.
#include "carrom/proto/json_codec.hpp"

#include "json_reader.hpp"
#include "message_names.hpp"

#include <cstddef>
#include <type_traits>
#include <vector>

namespace carrom::proto {

using detail::JsonReader;
using detail::Range;
using nlohmann::json;

namespace {

json encode_options(const RoomOptions& options) {
    json out = json::object();
    if (options.target_points) {
        out["target_points"] = *options.target_points;
    }
    if (options.boards) {
        out["boards"] = *options.boards;
    }
    if (options.shot_clock_s) {
        out["shot_clock_s"] = *options.shot_clock_s;
    }
    return out;
}

json encode_body(const Hello& m) {
    json out{{"version", m.version}, {"name", m.name}};
    if (m.resume_token) {
        out["resume_token"] = *m.resume_token;
    }
    if (m.identity) {
        out["identity"] = *m.identity;
    }
    if (m.follows_redirects) {
        out["follows_redirects"] = true;
    }
    return out;
}
// "seats" and "bot.seats" go on the wire only when they differ from the singles defaults, so a
// singles message is the same as before doubles.
json encode_body(const CreateRoom& m) {
    json out{{"rule_set", to_string(m.rule_set)}, {"options", encode_options(m.options)}};
    if (m.seats != 2) {
        out["seats"] = m.seats;
    }
    if (m.bot) {
        out["bot"] = json{{"level", to_string(m.bot->level)}};
        if (!m.bot->seats.empty()) {
            out["bot"]["seats"] = m.bot->seats;
        }
    }
    if (m.rated) {
        out["rated"] = true;
    }
    return out;
}
json encode_body(const JoinRoom& m) {
    return json{{"code", m.code}, {"as", to_string(m.as)}};
}
json encode_body(const QuickMatch& m) {
    json out{{"rule_set", to_string(m.rule_set)}};
    if (m.seats != 2) {
        out["seats"] = m.seats;
    }
    return out;
}
json encode_body(const Aim& m) {
    return json{{"turn", m.turn}, {"x", m.x_px}};
}
json encode_body(const Shoot& m) {
    return json{{"turn", m.turn}, {"x", m.x_px}, {"angle", m.angle_rad}, {"power", m.power}};
}
json encode_body(const Rematch&) {
    return json::object();
}
json encode_body(const Leave&) {
    return json::object();
}
json encode_body(const Ping& m) {
    return json{{"nonce", m.nonce}};
}
json encode_body(const EmoteMessage& m) {
    return json{{"emote", to_string(m.emote)}};
}

// Decoders: each reads its fields from `r`; the caller checks r.ok().
void decode_body(JsonReader& r, Hello& m) {
    m.version = r.small_int("version", 0, 1000000);
    m.name = r.text("name", 1, kMaxNameBytes);
    if (r.ok() && !is_player_name(m.name)) {
        r.fail("name", "must have a visible character");
    }
    if (r.has("resume_token")) {
        m.resume_token = r.text("resume_token", kResumeTokenLength, kResumeTokenLength);
        if (r.ok() && !is_resume_token(*m.resume_token)) {
            r.fail("resume_token", "must be 32 lowercase hexadecimal digits");
        }
    }
    if (r.has("identity")) {
        m.identity = r.text("identity", 1, kMaxIdentityBytes);
    }
    if (r.has("follows_redirects")) {
        m.follows_redirects = r.boolean("follows_redirects");
    }
}

void decode_options(JsonReader& r, RoomOptions& options) {
    if (r.has("target_points")) {
        options.target_points = r.small_int("target_points", 1, kMaxTargetPoints);
    }
    if (r.has("boards")) {
        options.boards = r.small_int("boards", 1, kMaxBoards);
    }
    if (r.has("shot_clock_s")) {
        options.shot_clock_s = r.number("shot_clock_s", {0.0, kMaxShotClockS});
    }
}

// "seats": 2 or 4 (absent: 2).
int decode_seat_count(JsonReader& r) {
    if (!r.has("seats")) {
        return 2;
    }
    const int seats = r.small_int("seats", 2, static_cast<int>(kMaxSeats));
    if (r.ok() && seats != 2 && seats != 4) {
        r.fail("seats", "must be 2 or 4");
    }
    return seats;
}

// "bot.seats": distinct seat indices in 1..seat_count-1, at least one.
std::vector<int> decode_bot_seats(JsonReader& r, int seat_count) {
    const auto max_items = static_cast<std::size_t>(seat_count - 1);
    std::vector<int> seats = r.int_array("seats", 1, seat_count - 1, max_items);
    if (!r.ok()) {
        return {};
    }
    if (seats.empty()) {
        r.fail("seats", "must name at least one seat");
        return {};
    }
    for (std::size_t i = 0; i < seats.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (seats[i] == seats[j]) {
                r.fail("seats", "must not name a seat twice");
                return {};
            }
        }
    }
    return seats;
}

void decode_body(JsonReader& r, CreateRoom& m) {
    m.seats = decode_seat_count(r);
    if (r.has("rule_set")) {
        m.rule_set = r.enumeration("rule_set", kRuleSetNames, RuleSet::Icf);
    }
    if (r.has("options")) {
        if (const json* options = r.object("options")) {
            JsonReader child = r.nested(*options, r.path_of("options"));
            decode_options(child, m.options);
            r.merge(child.error());
        }
    }
    if (r.has("bot")) {
        if (const json* bot = r.object("bot")) {
            JsonReader child = r.nested(*bot, r.path_of("bot"));
            BotSeat seat;
            if (child.has("level")) {
                seat.level = child.enumeration("level", kBotLevelNames, BotLevel::Medium);
            }
            if (child.has("seats") && r.ok()) {
                seat.seats = decode_bot_seats(child, m.seats);
            }
            r.merge(child.error());
            m.bot = seat;
        }
    }
    if (r.has("rated")) {
        m.rated = r.boolean("rated");
    }
}

void decode_body(JsonReader& r, JoinRoom& m) {
    m.code = r.text("code", kRoomCodeLength, kRoomCodeLength);
    if (r.ok() && !is_room_code(m.code)) {
        r.fail("code", "must be 6 characters from " + std::string(kRoomCodeAlphabet));
    }
    if (r.has("as")) {
        m.as = r.enumeration("as", kRoleNames, Role::Player);
    }
}

void decode_body(JsonReader& r, QuickMatch& m) {
    if (r.has("rule_set")) {
        m.rule_set = r.enumeration("rule_set", kRuleSetNames, RuleSet::Icf);
    }
    m.seats = decode_seat_count(r);
}

void decode_body(JsonReader& r, Aim& m) {
    m.turn = static_cast<int>(r.integer("turn", 0, kMaxTurn));
    m.x_px = r.number("x", {0.0, kMaxCoordinatePx});
}

void decode_body(JsonReader& r, Shoot& m) {
    m.turn = static_cast<int>(r.integer("turn", 0, kMaxTurn));
    m.x_px = r.number("x", {0.0, kMaxCoordinatePx});
    m.angle_rad = r.number("angle", {-kMaxAngleRad, kMaxAngleRad});
    m.power = r.number("power", {0.0, kMaxPower});
}

void decode_body(JsonReader&, Rematch&) {}
void decode_body(JsonReader&, Leave&) {}
void decode_body(JsonReader& r, Ping& m) {
    m.nonce = r.integer("nonce", 0, kMaxNonce);
}
void decode_body(JsonReader& r, EmoteMessage& m) {
    m.emote = r.enumeration("emote", kEmoteNames, Emote::NiceShot);
}

} // namespace

std::string_view type_name(const ClientMessage& message) {
    return detail::kClientTypeNames[message.index()];
}

json to_json(const ClientMessage& message) {
    return detail::encode_message(message, detail::kClientTypeNames,
                                  [](const auto& m) { return encode_body(m); });
}

DecodedMessage<ClientMessage> client_from_json(const json& value) {
    return detail::decode_message<ClientMessage>(
        value, detail::kClientTypeNames, [](JsonReader& r, auto& body) { decode_body(r, body); });
}

} // namespace carrom::proto
