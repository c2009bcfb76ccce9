// Fuzzes scene files (proto/scene_json.hpp, the format carrom-sim reads) and the exact engine:
// arbitrary text goes to decode_scene_text; a scene it accepts is simulated to rest with the
// trajectory recorded. Failures: a sanitizer report, an exception, the engine rejecting a scene
// the decoder accepted, or a non-finite position or velocity in the result or the trajectory
// (fuzz::fail, which aborts). libFuzzer's -timeout catches a simulation that does not end.
#include "carrom/exact_engine.hpp"
#include "carrom/proto/scene_json.hpp"
#include "fuzz.hpp"

#include <cmath>
#include <string>

namespace carrom::fuzz {
namespace {

bool finite(Vec2 v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

} // namespace

void scene_one_input(std::string_view text) {
    const auto decoded = proto::decode_scene_text(text);
    if (!decoded.ok()) {
        return;
    }
    ExactEngine engine(decoded.value.config);
    SimOptions options;
    options.record_trajectory = true;
    const auto out = engine.run(decoded.value.bodies, options);
    if (out.error || out.result == nullptr) {
        fail("scene: the engine rejects a scene that decode_scene_text accepted (" +
                 (out.error ? out.error->code : std::string("no result")) + ")",
             text);
    }
    for (const auto& body : out.result->bodies) {
        if (!finite(body.pos_px) || !finite(body.vel_px_s)) {
            fail("scene: body " + std::to_string(body.id) + " ends with a non-finite state", text);
        }
    }
    for (const auto& segment : out.result->trajectory.segments) {
        if (!std::isfinite(segment.t_s) || !finite(segment.pos_px) || !finite(segment.vel_px_s)) {
            fail("scene: a trajectory segment of body index " + std::to_string(segment.index) +
                     " is not finite",
                 text);
        }
    }
}

} // namespace carrom::fuzz
