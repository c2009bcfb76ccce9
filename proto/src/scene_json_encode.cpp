// Encoders for scene JSON. Doubles are written with enough digits to read back bit-identical.

#include "carrom/proto/scene_json.hpp"

namespace carrom::proto {

using Json = nlohmann::json;

namespace {

// Name and value of every config field, in the order of PhysicsConfig.
Json config_fields_to_json(const PhysicsConfig& c) {
    return Json{{"board_size_px", c.board_size_px},
                {"frame_px", c.frame_px},
                {"coin_radius_px", c.coin_radius_px},
                {"striker_radius_px", c.striker_radius_px},
                {"coin_mass", c.coin_mass},
                {"striker_mass", c.striker_mass},
                {"damping_per_s", c.damping_per_s},
                {"stop_speed_px_s", c.stop_speed_px_s},
                {"cushion_restitution", c.cushion_restitution},
                {"disc_restitution", c.disc_restitution},
                {"restitution_floor_px_s", c.restitution_floor_px_s},
                {"pocket_radius_px", c.pocket_radius_px},
                {"max_power", c.max_power},
                {"power_to_speed", c.power_to_speed},
                {"baseline_offset_px", c.baseline_offset_px},
                {"baseline_end_margin_px", c.baseline_end_margin_px},
                {"max_events", c.max_events}};
}

} // namespace

Json config_to_json(const PhysicsConfig& config) {
    return config_fields_to_json(config);
}

Json config_overrides_to_json(const PhysicsConfig& config) {
    const Json defaults = config_fields_to_json(PhysicsConfig{});
    const Json fields = config_fields_to_json(config);
    Json out = Json::object();
    for (const auto& item : fields.items()) {
        if (item.value() != defaults[item.key()]) {
            out[item.key()] = item.value();
        }
    }
    return out;
}

Json vec_to_json(Vec2 v) {
    return Json::array({v.x, v.y});
}

Json body_to_json(const Body& body) {
    return Json{{"id", body.id},
                {"kind", std::string(to_string(body.kind))},
                {"pos", vec_to_json(body.pos_px)},
                {"vel", vec_to_json(body.vel_px_s)},
                {"pocketed", body.pocketed}};
}

Json bodies_to_json(std::span<const Body> bodies) {
    Json out = Json::array();
    for (const Body& body : bodies) {
        out.push_back(body_to_json(body));
    }
    return out;
}

Json shot_to_json(const ShotSpec& spec) {
    return Json{{"baseline", enum_names::name_or_unknown(kBaselineNames, spec.baseline)},
                {"x", spec.shot.x_px},
                {"angle", spec.shot.angle_rad},
                {"power", spec.shot.power}};
}

Json event_to_json(const Event& event) {
    return Json{{"t_s", event.t_s},
                {"kind", std::string(to_string(event.kind))},
                {"a", event.a},
                {"b", event.b},
                {"impulse", event.impulse},
                {"pos", vec_to_json(event.pos_px)}};
}

Json events_to_json(std::span<const Event> events) {
    Json out = Json::array();
    for (const Event& event : events) {
        out.push_back(event_to_json(event));
    }
    return out;
}

Json scene_to_json(const SceneSpec& scene) {
    Json out{{"bodies", bodies_to_json(scene.bodies)}};
    Json overrides = config_overrides_to_json(scene.config);
    if (!overrides.empty()) {
        out["config"] = std::move(overrides);
    }
    return out;
}

Json stats_to_json(const SimStats& stats) {
    return Json{{"events", stats.events},
                {"contact_rounds", stats.contact_rounds},
                {"collapse_solves", stats.collapse_solves},
                {"pair_tests", stats.pair_tests}};
}

Json pocketed_ids_to_json(std::span<const Body> bodies) {
    Json out = Json::array();
    for (const Body& body : bodies) {
        if (body.pocketed) {
            out.push_back(body.id);
        }
    }
    return out;
}

Json sim_result_to_json(const SimResult& result) {
    return Json{{"end_time_s", result.end_time_s},
                {"truncated", result.truncated},
                {"events", events_to_json(result.events)},
                {"bodies", bodies_to_json(result.bodies)},
                {"pocketed", pocketed_ids_to_json(result.bodies)},
                {"stats", stats_to_json(result.stats)}};
}

Json error_to_json(const Error& error) {
    return Json{
        {"error", {{"code", error.code}, {"path", error.path}, {"message", error.message}}}};
}

} // namespace carrom::proto
