#pragma once
// Scenes: the set of bodies a simulation starts from. The standard layout, shots, and the
// validation every scene passes before it is simulated.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/enum_names.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace carrom {

// Ids of the standard layout: the queen is 0, the inner ring 1..6, the outer ring 7..18
// (the seed's order); the striker, when added by make_shot, is 19.
inline constexpr int kQueenId = 0;
inline constexpr int kStrikerId = 19;
inline constexpr int kCoinCount = 19;

// The seed's starting layout: queen at the centre, an inner ring of 6 at 2.5 r starting at the
// top (-90 degrees), an outer ring of 12 at 4.5 r offset by 15 degrees; colours alternate,
// black first in each ring. All at rest.
std::vector<Body> standard_layout(const PhysicsConfig& config);

// A shot as a player makes it: striker centre x on the shooter's baseline, direction angle in
// radians (0 = +x, pi/2 = +y, i.e. down the screen), power in [0, max_power].
struct Shot {
    double x_px = 300.0;
    double angle_rad = 0.0;
    double power = 0.0;
    friend bool operator==(const Shot&, const Shot&) = default;
};

// Which baseline a shot is taken from.
enum class Baseline { Bottom, Top };
inline constexpr enum_names::Table<Baseline, 2> kBaselineNames{
    {{Baseline::Bottom, "bottom"}, {Baseline::Top, "top"}}};

// y of a baseline: board_size - baseline_offset for the bottom one, baseline_offset for the top.
double baseline_y(const PhysicsConfig& config, Baseline baseline);
// The legal range of striker centre x on a baseline (the seed's [113, 487] by default).
double baseline_x_min(const PhysicsConfig& config);
double baseline_x_max(const PhysicsConfig& config);

// The striker body (id kStrikerId) for a shot: on the baseline at shot.x_px, moving at
// power * power_to_speed px/s in direction angle_rad. Does not validate the shot.
Body make_striker(const PhysicsConfig& config, Baseline baseline, const Shot& shot);

// A scene error names the body (by id, -1 for the scene as a whole) and the field.
struct SceneError {
    std::string code; // stable machine-readable code, e.g. "overlap", "outside_cushions"
    int body_id = -1;
    std::string field;   // e.g. "pos.x", "vel.y", "id"
    std::string message; // one plain sentence
};

// Rejects non-finite numbers, duplicate ids, bodies outside the cushions (by more than 1e-6 px,
// which covers rounding at a cushion contact), and overlapping
// unpocketed bodies (overlap beyond overlap_tolerance_px). Pocketed bodies are ignored except
// for finiteness and id checks.
std::optional<SceneError> validate_scene(const PhysicsConfig& config, std::span<const Body> bodies,
                                         double overlap_tolerance_px = 1e-9);

// validate_scene when some bodies are known to be valid together: bit i of known_pairs_ok set
// (i < 64) says body i is bit for bit a body of a scene that passed this validation with the
// same config and tolerance, at the same index, together with every other body whose bit is
// set. The overlap test then skips the pairs of two such bodies (they cannot overlap); every
// other check runs as before, so the answer, and the error reported first, are the same as
// validate_scene's. A bot's search validates thousands of scenes that differ in the striker only.
std::optional<SceneError> validate_scene(const PhysicsConfig& config, std::span<const Body> bodies,
                                         double overlap_tolerance_px, std::uint64_t known_pairs_ok);

} // namespace carrom
