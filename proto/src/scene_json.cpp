// Decoders for scene JSON (docs/carrom-sim.md). Every check names the JSON path of the value it
// rejects; the first problem found is returned, in a fixed order (document order of the known
// fields as listed here, not of the text).

#include "carrom/proto/scene_json.hpp"

#include "carrom/proto/limits.hpp"
#include "scene_json_read.hpp"

#include <array>
#include <string>
#include <unordered_set>
#include <vector>

namespace carrom::proto {

using namespace scene_json_detail;

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

MaybeError check_config_keys(const Json& j, const std::string& path) {
    if (!j.is_object()) {
        return check_object(j, path, {});
    }
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        bool known = key == "max_events";
        for (const ConfigField& field : config_fields()) {
            known = known || key == field.name;
        }
        if (!known) {
            return make_error(scene_code::kUnknownField, field_path(path, key),
                              "unknown field '" + key + "' in " + path);
        }
    }
    return std::nullopt;
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

MaybeError decode_kind(const Json& j, const std::string& path, BodyKind& out) {
    std::string text;
    if (auto e = read_string(j, path, 16, text)) {
        return e;
    }
    if (!parse_body_kind(text, out)) {
        return make_error(scene_code::kBadValue, path,
                          path + " must be \"black\", \"white\", \"queen\" or \"striker\"");
    }
    return std::nullopt;
}

MaybeError decode_baseline(const Json& j, const std::string& path, carrom::Baseline& out) {
    std::string text;
    if (auto e = read_string(j, path, 16, text)) {
        return e;
    }
    if (text != "bottom" && text != "top") {
        return make_error(scene_code::kBadValue, path, path + " must be \"bottom\" or \"top\"");
    }
    out = text == "bottom" ? carrom::Baseline::Bottom : carrom::Baseline::Top;
    return std::nullopt;
}

MaybeError decode_bodies(const Json& j, const std::string& path, std::vector<Body>& out) {
    if (!j.is_array()) {
        return wrong_type(path, j, "an array");
    }
    if (j.size() > kMaxSceneBodies) {
        return make_error(scene_code::kTooMany, path,
                          path + " has " + std::to_string(j.size()) + " bodies; at most " +
                              std::to_string(kMaxSceneBodies) + " are allowed");
    }
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        auto body = decode_body(j[i], index_path(path, i));
        if (!body.ok()) {
            return body.error;
        }
        out.push_back(body.value);
    }
    return std::nullopt;
}

MaybeError decode_layout(const Json& j, std::vector<Body>& out, const PhysicsConfig& config) {
    std::string name;
    if (auto e = read_string(j, "layout", 32, name)) {
        return e;
    }
    if (name != "standard") {
        return make_error(scene_code::kBadValue, "layout", "layout must be \"standard\"");
    }
    out = standard_layout(config);
    return std::nullopt;
}

// Where a validate_scene error points in the document: bodies from the "bodies" array by index,
// the shot's striker at "shot", layout bodies at "layout". A duplicate id points at the second
// body with that id.
JsonError scene_error_to_json(const SceneError& error, const Json& doc,
                              std::span<const Body> bodies) {
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
    return JsonError{error.code, path, error.message};
}

MaybeError decode_stats(const Json& j, const std::string& path, SimStats& out) {
    if (auto e =
            check_object(j, path, {"events", "contact_rounds", "collapse_solves", "pair_tests"})) {
        return e;
    }
    const std::pair<std::string_view, int*> fields[] = {{"events", &out.events},
                                                        {"contact_rounds", &out.contact_rounds},
                                                        {"collapse_solves", &out.collapse_solves},
                                                        {"pair_tests", &out.pair_tests}};
    for (const auto& [name, member] : fields) {
        if (auto e = require_field(j, name, path)) {
            return e;
        }
        std::int64_t v = 0;
        if (auto e = read_integer(j[name], field_path(path, name), 0, 2147483647, v)) {
            return e;
        }
        *member = static_cast<int>(v);
    }
    return std::nullopt;
}

MaybeError decode_events(const Json& j, const std::string& path, std::vector<Event>& out) {
    if (!j.is_array()) {
        return wrong_type(path, j, "an array");
    }
    if (j.size() > kMaxEvents) {
        return make_error(scene_code::kTooMany, path, path + " has too many events");
    }
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        auto event = decode_event(j[i], index_path(path, i));
        if (!event.ok()) {
            return event.error;
        }
        out.push_back(event.value);
    }
    return std::nullopt;
}

} // namespace

Decoded<nlohmann::json> parse_json_text(std::string_view text, std::size_t max_bytes) {
    Decoded<Json> out;
    if (text.size() > max_bytes) {
        out.error = make_error(scene_code::kTooLarge, "",
                               "the text is " + std::to_string(text.size()) + " bytes; at most " +
                                   std::to_string(max_bytes) + " are allowed");
        return out;
    }
    if (nesting_depth(text) > kMaxJsonDepth) {
        out.error = make_error(scene_code::kTooDeep, "",
                               "arrays and objects are nested more than " +
                                   std::to_string(kMaxJsonDepth) + " deep");
        return out;
    }
    // The JSON library ends the input at a NUL byte and would ignore what follows; JSON never
    // holds a raw NUL (not even inside a string), so any NUL makes the text malformed.
    if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
        out.error =
            make_error(scene_code::kMalformedJson, "",
                       "the text is not valid JSON: a NUL byte at offset " + std::to_string(nul));
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
        out.error = make_error(scene_code::kMalformedJson, "",
                               "the text is not valid JSON: " + printable_ascii(e.what()));
        return out;
    } catch (const std::exception& e) {
        out.error = make_error(scene_code::kMalformedJson, "",
                               "the text could not be parsed: " + printable_ascii(e.what()));
        return out;
    }
    if (!keys.duplicate.empty()) {
        out.value = Json();
        out.error = make_error(scene_code::kDuplicateKey, "",
                               "the key '" + keys.duplicate + "' appears twice in one object");
    }
    return out;
}

Decoded<PhysicsConfig> decode_config(const nlohmann::json& j, const PhysicsConfig& base,
                                     const std::string& path) {
    Decoded<PhysicsConfig> out;
    out.value = base;
    if (auto e = check_config_keys(j, path)) {
        out.error = e;
        return out;
    }
    for (const ConfigField& field : config_fields()) {
        if (!j.contains(field.name)) {
            continue;
        }
        auto e = read_number(j[field.name], field_path(path, field.name), field.range,
                             out.value.*(field.member));
        if (e) {
            out.error = e;
            return out;
        }
    }
    if (j.contains("max_events")) {
        std::int64_t v = 0;
        if (auto e = read_integer(j["max_events"], field_path(path, "max_events"), 1,
                                  kMaxEventsLimit, v)) {
            out.error = e;
            return out;
        }
        out.value.max_events = static_cast<int>(v);
    }
    if (auto problem = validate_config(out.value)) {
        out.error = make_error(scene_code::kInvalidConfig, field_path(path, problem->field),
                               problem->message);
    }
    return out;
}

Decoded<Body> decode_body(const nlohmann::json& j, const std::string& path) {
    Decoded<Body> out;
    auto fail = [&out](JsonError e) {
        out.error = std::move(e);
        return out;
    };
    if (auto e = check_object(j, path, {"id", "kind", "pos", "vel", "pocketed"})) {
        return fail(*e);
    }
    for (std::string_view key : {"id", "kind", "pos"}) {
        if (auto e = require_field(j, key, path)) {
            return fail(*e);
        }
    }
    std::int64_t id = 0;
    if (auto e = read_integer(j["id"], field_path(path, "id"), 0, kMaxBodyId, id)) {
        return fail(*e);
    }
    out.value.id = static_cast<int>(id);
    if (auto e = decode_kind(j["kind"], field_path(path, "kind"), out.value.kind)) {
        return fail(*e);
    }
    if (auto e = read_vec(j["pos"], field_path(path, "pos"), kMaxCoordinatePx, out.value.pos_px)) {
        return fail(*e);
    }
    if (j.contains("vel")) {
        if (auto e =
                read_vec(j["vel"], field_path(path, "vel"), kMaxSpeedPxS, out.value.vel_px_s)) {
            return fail(*e);
        }
    }
    if (j.contains("pocketed")) {
        if (auto e = read_bool(j["pocketed"], field_path(path, "pocketed"), out.value.pocketed)) {
            return fail(*e);
        }
    }
    return out;
}

Decoded<ShotSpec> decode_shot(const nlohmann::json& j, const PhysicsConfig& config,
                              const std::string& path) {
    Decoded<ShotSpec> out;
    auto fail = [&out](JsonError e) {
        out.error = std::move(e);
        return out;
    };
    if (auto e = check_object(j, path, {"baseline", "x", "angle", "power"})) {
        return fail(*e);
    }
    for (std::string_view key : {"x", "angle", "power"}) {
        if (auto e = require_field(j, key, path)) {
            return fail(*e);
        }
    }
    if (j.contains("baseline")) {
        if (auto e =
                decode_baseline(j["baseline"], field_path(path, "baseline"), out.value.baseline)) {
            return fail(*e);
        }
    }
    Shot& shot = out.value.shot;
    const Range x_range{baseline_x_min(config), baseline_x_max(config)};
    if (auto e = read_number(j["x"], field_path(path, "x"), x_range, shot.x_px)) {
        return fail(*e);
    }
    if (auto e = read_number(j["angle"], field_path(path, "angle"), {-kMaxAngleRad, kMaxAngleRad},
                             shot.angle_rad)) {
        return fail(*e);
    }
    if (auto e = read_number(j["power"], field_path(path, "power"), {0.0, config.max_power},
                             shot.power)) {
        return fail(*e);
    }
    return out;
}

Decoded<SceneSpec> decode_scene(const nlohmann::json& j) {
    Decoded<SceneSpec> out;
    auto fail = [&out](JsonError e) {
        out.error = std::move(e);
        return out;
    };
    if (auto e = check_object(j, "", {"description", "config", "bodies", "layout", "shot"})) {
        return fail(*e);
    }
    if (j.contains("description")) {
        std::string text;
        if (auto e = read_string(j["description"], "description", kMaxDescriptionBytes, text)) {
            return fail(*e);
        }
    }
    if (j.contains("config")) {
        auto config = decode_config(j["config"]);
        if (!config.ok()) {
            return fail(*config.error);
        }
        out.value.config = config.value;
    }
    const PhysicsConfig& config = out.value.config;
    if (j.contains("bodies") && j.contains("layout")) {
        return fail(make_error(scene_code::kConflict, "layout",
                               "give either \"bodies\" or \"layout\", not both"));
    }
    if (!j.contains("bodies") && !j.contains("layout")) {
        return fail(make_error(scene_code::kMissingField, "bodies",
                               "the scene needs \"bodies\" or \"layout\""));
    }
    auto e = j.contains("bodies") ? decode_bodies(j["bodies"], "bodies", out.value.bodies)
                                  : decode_layout(j["layout"], out.value.bodies, config);
    if (e) {
        return fail(*e);
    }
    if (j.contains("shot")) {
        auto shot = decode_shot(j["shot"], config);
        if (!shot.ok()) {
            return fail(*shot.error);
        }
        out.value.bodies.push_back(make_striker(config, shot.value.baseline, shot.value.shot));
    }
    if (auto problem = validate_scene(config, out.value.bodies)) {
        return fail(scene_error_to_json(*problem, j, out.value.bodies));
    }
    return out;
}

Decoded<SceneSpec> decode_scene_text(std::string_view text) {
    auto parsed = parse_json_text(text);
    if (!parsed.ok()) {
        return Decoded<SceneSpec>{{}, parsed.error};
    }
    return decode_scene(parsed.value);
}

Decoded<Event> decode_event(const nlohmann::json& j, const std::string& path) {
    Decoded<Event> out;
    auto fail = [&out](JsonError e) {
        out.error = std::move(e);
        return out;
    };
    if (auto e = check_object(j, path, {"t_s", "kind", "a", "b", "impulse", "pos"})) {
        return fail(*e);
    }
    for (std::string_view key : {"t_s", "kind", "a", "b", "impulse", "pos"}) {
        if (auto e = require_field(j, key, path)) {
            return fail(*e);
        }
    }
    Event& event = out.value;
    if (auto e = read_number(j["t_s"], field_path(path, "t_s"), {0.0, kMaxMatchTimeS}, event.t_s)) {
        return fail(*e);
    }
    std::string kind;
    if (auto e = read_string(j["kind"], field_path(path, "kind"), 16, kind)) {
        return fail(*e);
    }
    bool known = false;
    for (EventKind k :
         {EventKind::Collision, EventKind::Cushion, EventKind::Pocket, EventKind::Stop}) {
        if (kind == to_string(k)) {
            event.kind = k;
            known = true;
        }
    }
    if (!known) {
        return fail(make_error(scene_code::kBadValue, field_path(path, "kind"),
                               field_path(path, "kind") +
                                   " must be \"collision\", \"cushion\", \"pocket\" or \"stop\""));
    }
    std::int64_t a = 0;
    std::int64_t b = 0;
    if (auto e = read_integer(j["a"], field_path(path, "a"), 0, kMaxBodyId, a)) {
        return fail(*e);
    }
    if (auto e = read_integer(j["b"], field_path(path, "b"), -1, kMaxBodyId, b)) {
        return fail(*e);
    }
    event.a = static_cast<int>(a);
    event.b = static_cast<int>(b);
    if (auto e = read_number(j["impulse"], field_path(path, "impulse"), {0.0, kMaxImpulse},
                             event.impulse)) {
        return fail(*e);
    }
    if (auto e = read_vec(j["pos"], field_path(path, "pos"), kMaxCoordinatePx, event.pos_px)) {
        return fail(*e);
    }
    return out;
}

Decoded<SimResult> decode_sim_result(const nlohmann::json& j) {
    Decoded<SimResult> out;
    auto fail = [&out](JsonError e) {
        out.error = std::move(e);
        return out;
    };
    if (auto e = check_object(
            j, "", {"end_time_s", "truncated", "events", "bodies", "pocketed", "stats"})) {
        return fail(*e);
    }
    for (std::string_view key : {"end_time_s", "truncated", "events", "bodies", "stats"}) {
        if (auto e = require_field(j, key, "")) {
            return fail(*e);
        }
    }
    SimResult& result = out.value;
    if (auto e =
            read_number(j["end_time_s"], "end_time_s", {0.0, kMaxMatchTimeS}, result.end_time_s)) {
        return fail(*e);
    }
    if (auto e = read_bool(j["truncated"], "truncated", result.truncated)) {
        return fail(*e);
    }
    if (auto e = decode_events(j["events"], "events", result.events)) {
        return fail(*e);
    }
    if (auto e = decode_bodies(j["bodies"], "bodies", result.bodies)) {
        return fail(*e);
    }
    if (auto e = decode_stats(j["stats"], "stats", result.stats)) {
        return fail(*e);
    }
    if (j.contains("pocketed") && j["pocketed"] != pocketed_ids_to_json(result.bodies)) {
        return fail(make_error(scene_code::kBadValue, "pocketed",
                               "pocketed must list the ids of the pocketed bodies in order"));
    }
    return out;
}

} // namespace carrom::proto
