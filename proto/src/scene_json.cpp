// Decoders for scene JSON (docs/carrom-sim.md), read with JsonReader in the Document wording.
// Every check names the JSON path of the value it rejects; the first problem found is returned, in
// a fixed order (the order of the known fields as listed here, not of the text).

#include "carrom/proto/scene_json.hpp"

#include "carrom/proto/limits.hpp"
#include "json_reader.hpp"

#include <array>
#include <string>
#include <unordered_set>
#include <vector>

namespace carrom::proto {

using Json = nlohmann::json;
using namespace detail; // JsonReader, Wording, Range, field_path, index_path

namespace {

// Every overridable config field with its allowed range (validate_config then checks the
// relations between fields).
struct ConfigField {
    std::string_view name;
    double PhysicsConfig::*member;
    Range range;
};

const std::array<ConfigField, 16>& config_fields() {
    static const std::array<ConfigField, 16> fields{{
        {"board_size_px", &PhysicsConfig::board_size_px, {0.0, 1e5, true}},
        {"frame_px", &PhysicsConfig::frame_px, {0.0, 1e5}},
        {"coin_radius_px", &PhysicsConfig::coin_radius_px, {0.0, 1e4, true}},
        {"striker_radius_px", &PhysicsConfig::striker_radius_px, {0.0, 1e4, true}},
        {"coin_mass", &PhysicsConfig::coin_mass, {0.0, 1e6, true}},
        {"striker_mass", &PhysicsConfig::striker_mass, {0.0, 1e6, true}},
        {"damping_per_s", &PhysicsConfig::damping_per_s, {0.0, 1e3}},
        {"stop_speed_px_s", &PhysicsConfig::stop_speed_px_s, {0.0, 1e6, true}},
        {"cushion_restitution", &PhysicsConfig::cushion_restitution, {0.0, 1.0}},
        {"disc_restitution", &PhysicsConfig::disc_restitution, {0.0, 1.0}},
        {"restitution_floor_px_s", &PhysicsConfig::restitution_floor_px_s, {0.0, 1e6}},
        {"pocket_radius_px", &PhysicsConfig::pocket_radius_px, {0.0, 1e4, true}},
        {"max_power", &PhysicsConfig::max_power, {0.0, kMaxPower, true}},
        {"power_to_speed", &PhysicsConfig::power_to_speed, {0.0, 1e4, true}},
        {"baseline_offset_px", &PhysicsConfig::baseline_offset_px, {0.0, 1e5}},
        {"baseline_end_margin_px", &PhysicsConfig::baseline_end_margin_px, {0.0, 1e5}},
    }};
    return fields;
}

// The largest max_events a scene may ask for: with the engine's pair-test bound it keeps any
// accepted scene to about a second of work (docs/carrom-sim.md).
constexpr std::int64_t kMaxEventsLimit = 500000;

// The names config objects may hold: every ConfigField and "max_events".
const std::array<std::string_view, 17>& config_keys() {
    static const std::array<std::string_view, 17> keys = [] {
        std::array<std::string_view, 17> out{};
        for (std::size_t i = 0; i < config_fields().size(); ++i) {
            out[i] = config_fields()[i].name;
        }
        out.back() = "max_events";
        return out;
    }();
    return keys;
}

Error document_error(std::string_view code, std::string path, std::string message) {
    return Error{std::string(code), std::move(message), std::move(path)};
}

template <class T> Decoded<T> decoded(T value, const JsonReader& r) {
    return Decoded<T>{std::move(value), r.error()};
}

// Parser callback state: one set of keys per open object, to reject duplicate keys.
struct KeyTracker {
    std::vector<std::unordered_set<std::string>> open;
    std::string duplicate;
};

// Maximum nesting of arrays and objects, counted without parsing (strings are skipped), so that
// hostile input cannot make the recursive parts of the JSON library go deep.
std::size_t nesting_depth(std::string_view text) {
    std::size_t depth = 0;
    std::size_t deepest = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\') {
                ++i;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

// The parser's messages quote the input, which may not be UTF-8: keep them printable ASCII so
// that they can be written into JSON.
std::string printable_ascii(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        if (c < 0x20 || c > 0x7e) {
            c = '?';
        }
    }
    return out;
}

// [x, y] or {"x": x, "y": y} at r's key, each component in [-limit, limit]; component paths end
// in ".x" / ".y".
Vec2 read_vec(JsonReader& r, std::string_view key, double limit) {
    Vec2 out;
    const Json* j = r.find(key);
    if (j == nullptr) {
        return out;
    }
    const std::string path = r.path_of(key);
    const Range range{-limit, limit};
    if (j->is_array()) {
        if (j->size() != 2) {
            r.fail_at(path, "must be [x, y], not an array of " + std::to_string(j->size()),
                      scene_code::kWrongType);
            return out;
        }
        out.x = r.number_at((*j)[0], field_path(path, "x"), range);
        out.y = r.number_at((*j)[1], field_path(path, "y"), range);
    } else if (j->is_object()) {
        JsonReader v = r.nested(*j, path);
        if (v.only_keys({"x", "y"}) && v.require({"x", "y"})) {
            out.x = v.number("x", range);
            out.y = v.number("y", range);
        }
        r.merge(v.error());
    } else {
        r.wrong_type(*j, path, "[x, y]");
    }
    return out;
}

// An array at r's key of at most max_items values, each read by decode_item(value, path) (which
// returns a Decoded<T>); too_many(path, size) words the error for a longer array.
template <class T, class DecodeItem, class TooMany>
std::vector<T> read_array(JsonReader& r, std::string_view key, std::size_t max_items,
                          DecodeItem decode_item, TooMany too_many) {
    std::vector<T> out;
    const Json* j = r.find(key);
    if (j == nullptr) {
        return out;
    }
    const std::string path = r.path_of(key);
    if (!j->is_array()) {
        r.wrong_type(*j, path, "an array");
    } else if (j->size() > max_items) {
        r.merge(document_error(scene_code::kTooMany, path, too_many(path, j->size())));
    }
    for (std::size_t i = 0; r.ok() && i < j->size(); ++i) {
        auto item = decode_item((*j)[i], index_path(path, i));
        r.merge(item.error);
        out.push_back(std::move(item.value));
    }
    return out;
}

// An array of at most kMaxSceneBodies bodies.
std::vector<Body> read_bodies(JsonReader& r, std::string_view key) {
    return read_array<Body>(r, key, kMaxSceneBodies, &decode_body,
                            [](const std::string& path, std::size_t size) {
                                return path + " has " + std::to_string(size) + " bodies; at most " +
                                       std::to_string(kMaxSceneBodies) + " are allowed";
                            });
}

// Where a validate_scene error points in the document: bodies from the "bodies" array by index,
// the shot's striker at "shot", layout bodies at "layout". A duplicate id points at the second
// body with that id.
Error scene_error_to_json(const SceneError& error, const Json& doc, std::span<const Body> bodies) {
    std::string path;
    int skip = error.code == "duplicate_id" ? 1 : 0;
    for (std::size_t i = 0; i < bodies.size() && path.empty(); ++i) {
        if (bodies[i].id != error.body_id || skip-- > 0) {
            continue;
        }
        if (doc.contains("bodies") && i < doc["bodies"].size()) {
            path = field_path(index_path("bodies", i), error.field);
        } else if (doc.contains("shot") && i + 1 == bodies.size()) {
            path = "shot";
        } else {
            path = "layout";
        }
    }
    return document_error(error.code, path, error.message);
}

SimStats read_stats(JsonReader& parent, std::string_view key) {
    SimStats out;
    const Json* j = parent.find(key);
    if (j == nullptr) {
        return out;
    }
    JsonReader r = parent.nested(*j, parent.path_of(key));
    if (r.only_keys({"events", "contact_rounds", "collapse_solves", "pair_tests"})) {
        out.events = r.small_int("events", 0, 2147483647);
        out.contact_rounds = r.small_int("contact_rounds", 0, 2147483647);
        out.collapse_solves = r.small_int("collapse_solves", 0, 2147483647);
        out.pair_tests = r.small_int("pair_tests", 0, 2147483647);
    }
    parent.merge(r.error());
    return out;
}

std::vector<Event> read_events(JsonReader& r, std::string_view key) {
    return read_array<Event>(
        r, key, kMaxEvents, &decode_event,
        [](const std::string& path, std::size_t) { return path + " has too many events"; });
}

} // namespace

Decoded<nlohmann::json> parse_json_text(std::string_view text, std::size_t max_bytes) {
    Decoded<Json> out;
    if (text.size() > max_bytes) {
        out.error =
            document_error(scene_code::kTooLarge, "",
                           "the text is " + std::to_string(text.size()) + " bytes; at most " +
                               std::to_string(max_bytes) + " are allowed");
        return out;
    }
    if (nesting_depth(text) > kMaxJsonDepth) {
        out.error = document_error(scene_code::kTooDeep, "",
                                   "arrays and objects are nested more than " +
                                       std::to_string(kMaxJsonDepth) + " deep");
        return out;
    }
    // The JSON library ends the input at a NUL byte and would ignore what follows; JSON never
    // holds a raw NUL (not even inside a string), so any NUL makes the text malformed.
    if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
        out.error = document_error(scene_code::kMalformedJson, "",
                                   "the text is not valid JSON: a NUL byte at offset " +
                                       std::to_string(nul));
        return out;
    }
    KeyTracker keys;
    const Json::parser_callback_t track = [&keys](int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) {
            keys.open.emplace_back();
        } else if (event == Json::parse_event_t::object_end && !keys.open.empty()) {
            keys.open.pop_back();
        } else if (event == Json::parse_event_t::key && !keys.open.empty() &&
                   !keys.open.back().insert(parsed.get<std::string>()).second &&
                   keys.duplicate.empty()) {
            keys.duplicate = parsed.get<std::string>();
        }
        return true;
    };
    try {
        out.value = Json::parse(text.begin(), text.end(), track);
    } catch (const Json::exception& e) {
        out.error = document_error(scene_code::kMalformedJson, "",
                                   "the text is not valid JSON: " + printable_ascii(e.what()));
        return out;
    } catch (const std::exception& e) {
        out.error = document_error(scene_code::kMalformedJson, "",
                                   "the text could not be parsed: " + printable_ascii(e.what()));
        return out;
    }
    if (!keys.duplicate.empty()) {
        out.value = Json();
        out.error = document_error(scene_code::kDuplicateKey, "",
                                   "the key '" + keys.duplicate + "' appears twice in one object");
    }
    return out;
}

Decoded<PhysicsConfig> decode_config(const nlohmann::json& j, const PhysicsConfig& base,
                                     const std::string& path) {
    PhysicsConfig out = base;
    JsonReader r(j, path, Wording::Document);
    if (!r.only_keys(config_keys())) {
        return decoded(out, r);
    }
    for (const ConfigField& field : config_fields()) {
        if (r.has(field.name)) {
            out.*(field.member) = r.number(field.name, field.range);
        }
    }
    if (r.has("max_events")) {
        out.max_events = static_cast<int>(r.integer("max_events", 1, kMaxEventsLimit));
    }
    if (r.ok()) {
        if (auto problem = validate_config(out)) {
            r.merge(document_error(scene_code::kInvalidConfig, field_path(path, problem->field),
                                   problem->message));
        }
    }
    return decoded(out, r);
}

Decoded<Body> decode_body(const nlohmann::json& j, const std::string& path) {
    Body out;
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"id", "kind", "pos", "vel", "pocketed"}) && r.require({"id", "kind", "pos"})) {
        out.id = static_cast<int>(r.integer("id", 0, kMaxBodyId));
        out.kind = r.enumeration("kind", kBodyKindNames, BodyKind::Black);
        out.pos_px = read_vec(r, "pos", kMaxCoordinatePx);
        if (r.has("vel")) {
            out.vel_px_s = read_vec(r, "vel", kMaxSpeedPxS);
        }
        if (r.has("pocketed")) {
            out.pocketed = r.boolean("pocketed");
        }
    }
    return decoded(out, r);
}

Decoded<ShotSpec> decode_shot(const nlohmann::json& j, const PhysicsConfig& config,
                              const std::string& path) {
    ShotSpec out;
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"baseline", "x", "angle", "power"}) && r.require({"x", "angle", "power"})) {
        if (r.has("baseline")) {
            out.baseline = r.enumeration("baseline", kBaselineNames, carrom::Baseline::Bottom);
        }
        out.shot.x_px = r.number("x", {baseline_x_min(config), baseline_x_max(config)});
        out.shot.angle_rad = r.number("angle", {-kMaxAngleRad, kMaxAngleRad});
        out.shot.power = r.number("power", {0.0, config.max_power});
    }
    return decoded(out, r);
}

Decoded<SceneSpec> decode_scene(const nlohmann::json& j) {
    SceneSpec out;
    JsonReader r(j, "", Wording::Document);
    if (!r.only_keys({"description", "config", "bodies", "layout", "shot"})) {
        return decoded(std::move(out), r);
    }
    if (r.has("description")) {
        r.text("description", 0, kMaxDescriptionBytes);
    }
    if (const Json* config = r.has("config") ? r.find("config") : nullptr) {
        auto decoded_config = decode_config(*config);
        r.merge(decoded_config.error);
        out.config = decoded_config.value;
    }
    if (r.has("bodies") && r.has("layout")) {
        r.merge(document_error(scene_code::kConflict, "layout",
                               "give either \"bodies\" or \"layout\", not both"));
    } else if (r.ok() && !r.has("bodies") && !r.has("layout")) {
        r.merge(document_error(scene_code::kMissingField, "bodies",
                               "the scene needs \"bodies\" or \"layout\""));
    }
    if (r.has("bodies")) {
        out.bodies = read_bodies(r, "bodies");
    } else if (r.has("layout") && r.text("layout", 0, 32) != "standard" && r.ok()) {
        r.fail("layout", "must be \"standard\"");
    } else if (r.ok()) {
        out.bodies = standard_layout(out.config);
    }
    if (const Json* shot = r.has("shot") ? r.find("shot") : nullptr) {
        auto decoded_shot = decode_shot(*shot, out.config);
        r.merge(decoded_shot.error);
        out.bodies.push_back(
            make_striker(out.config, decoded_shot.value.baseline, decoded_shot.value.shot));
    }
    if (r.ok()) {
        if (auto problem = validate_scene(out.config, out.bodies)) {
            r.merge(scene_error_to_json(*problem, j, out.bodies));
        }
    }
    return decoded(std::move(out), r);
}

Decoded<SceneSpec> decode_scene_text(std::string_view text) {
    auto parsed = parse_json_text(text);
    if (!parsed.ok()) {
        return Decoded<SceneSpec>{{}, parsed.error};
    }
    return decode_scene(parsed.value);
}

Decoded<Event> decode_event(const nlohmann::json& j, const std::string& path) {
    Event out;
    JsonReader r(j, path, Wording::Document);
    if (r.only_keys({"t_s", "kind", "a", "b", "impulse", "pos"}) &&
        r.require({"t_s", "kind", "a", "b", "impulse", "pos"})) {
        out.t_s = r.number("t_s", {0.0, kMaxMatchTimeS});
        out.kind = r.enumeration("kind", kEventKindNames, EventKind::Collision);
        out.a = static_cast<int>(r.integer("a", 0, kMaxBodyId));
        out.b = static_cast<int>(r.integer("b", -1, kMaxBodyId));
        out.impulse = r.number("impulse", {0.0, kMaxImpulse});
        out.pos_px = read_vec(r, "pos", kMaxCoordinatePx);
    }
    return decoded(out, r);
}

Decoded<SimResult> decode_sim_result(const nlohmann::json& j) {
    SimResult out;
    JsonReader r(j, "", Wording::Document);
    if (r.only_keys({"end_time_s", "truncated", "events", "bodies", "pocketed", "stats"}) &&
        r.require({"end_time_s", "truncated", "events", "bodies", "stats"})) {
        out.end_time_s = r.number("end_time_s", {0.0, kMaxMatchTimeS});
        out.truncated = r.boolean("truncated");
        out.events = read_events(r, "events");
        out.bodies = read_bodies(r, "bodies");
        out.stats = read_stats(r, "stats");
    }
    if (r.has("pocketed") && j["pocketed"] != pocketed_ids_to_json(out.bodies)) {
        r.merge(document_error(scene_code::kBadValue, "pocketed",
                               "pocketed must list the ids of the pocketed bodies in order"));
    }
    return decoded(std::move(out), r);
}

} // namespace carrom::proto
