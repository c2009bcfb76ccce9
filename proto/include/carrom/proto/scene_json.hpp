#pragma once
// JSON codec for physics data: config overrides, bodies, shots, scenes, events and simulation
// results (docs/carrom-sim.md describes the format). Decoding untrusted text never throws: every
// decoder returns either a value or an Error (error.hpp) naming the offending value by its JSON
// path (e.g. "bodies[3].vel.x") with a stable code (scene_code::*) and one sentence.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/event.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/proto/error.hpp"
#include "carrom/scene.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace carrom::proto {

inline constexpr std::size_t kMaxSceneBytes = 1 << 20; // 1 MiB of scene text
inline constexpr std::size_t kMaxJsonDepth = 16;       // nested arrays and objects
inline constexpr std::size_t kMaxSceneBodies = 64;
inline constexpr int kMaxBodyId = 1000000;          // ids are integers in [0, kMaxBodyId]
inline constexpr std::size_t kMaxEvents = 10000000; // events in a decoded result
inline constexpr std::size_t kMaxDescriptionBytes = 2000;

// A value or the first problem found; value is meaningful only when ok().
template <class T> struct Decoded {
    T value{};
    std::optional<Error> error;
    bool ok() const { return !error.has_value(); }
};

// A shot from a named baseline.
struct ShotSpec {
    carrom::Baseline baseline = carrom::Baseline::Bottom;
    Shot shot;
};

// A decoded scene, ready to simulate: the config with overrides applied and every body
// (for "layout": "standard", the standard layout; plus the striker when a shot is given).
struct SceneSpec {
    PhysicsConfig config;
    std::vector<Body> bodies;
};

// Parses text with size and depth limits and rejects duplicate keys and NUL bytes.
Decoded<nlohmann::json> parse_json_text(std::string_view text,
                                        std::size_t max_bytes = kMaxSceneBytes);

// Applies the overrides in j (an object; every field optional, unknown keys rejected) to base,
// then runs validate_config.
Decoded<PhysicsConfig> decode_config(const nlohmann::json& j, const PhysicsConfig& base = {},
                                     const std::string& path = "config");
// {"id": 0, "kind": "queen", "pos": [x, y], "vel": [vx, vy], "pocketed": false}; vel and
// pocketed are optional; a vector may also be {"x": .., "y": ..}. Does not check the cushions.
Decoded<Body> decode_body(const nlohmann::json& j, const std::string& path);
// {"baseline": "bottom" | "top", "x": px, "angle": rad, "power": p}; baseline is optional
// (bottom). x must lie on the baseline's range and power in [0, config.max_power].
Decoded<ShotSpec> decode_shot(const nlohmann::json& j, const PhysicsConfig& config,
                              const std::string& path = "shot");
// {"description"?, "config"?, "bodies" | "layout": "standard", "shot"?}; runs validate_scene.
Decoded<SceneSpec> decode_scene(const nlohmann::json& j);
Decoded<SceneSpec> decode_scene_text(std::string_view text);
// {"t_s", "kind", "a", "b", "impulse", "pos"}.
Decoded<carrom::Event> decode_event(const nlohmann::json& j, const std::string& path);
// The output of sim_result_to_json (without the trajectory).
Decoded<SimResult> decode_sim_result(const nlohmann::json& j);

nlohmann::json config_to_json(const PhysicsConfig& config); // every field
// Only the fields that differ from PhysicsConfig{}: an empty object for the defaults.
nlohmann::json config_overrides_to_json(const PhysicsConfig& config);
nlohmann::json vec_to_json(Vec2 v); // [x, y]
nlohmann::json body_to_json(const Body& body);
nlohmann::json bodies_to_json(std::span<const Body> bodies);
nlohmann::json shot_to_json(const ShotSpec& shot);
nlohmann::json event_to_json(const carrom::Event& event);
nlohmann::json events_to_json(std::span<const carrom::Event> events);
nlohmann::json scene_to_json(const SceneSpec& scene); // {"config"?, "bodies"}
nlohmann::json stats_to_json(const SimStats& stats);
// Ids of the pocketed bodies, in body order.
nlohmann::json pocketed_ids_to_json(std::span<const Body> bodies);
// {"end_time_s", "truncated", "events", "bodies", "pocketed", "stats"}.
nlohmann::json sim_result_to_json(const SimResult& result);
nlohmann::json error_to_json(const Error& error); // {"error": {"code", "path", "message"}}

} // namespace carrom::proto
