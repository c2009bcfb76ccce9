#include "carrom/scene.hpp"
#include "carrom/det_math.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

namespace carrom {

namespace {

// cos and sin of an angle given in whole degrees, reduced to the first quadrant first so that
// mirror-image angles (a and 180 - a) give exactly negated x offsets and exact zeros on the axes.
// This keeps the standard layout exactly mirror-symmetric about x = centre.
Vec2 unit_at_degrees(int degrees) {
    int a = ((degrees % 360) + 360) % 360;
    double sx = 1.0;
    double sy = 1.0;
    if (a > 180) {
        a = 360 - a;
        sy = -1.0;
    }
    if (a > 90) {
        a = 180 - a;
        sx = -1.0;
    }
    if (a == 0) {
        return {sx, 0.0};
    }
    if (a == 90) {
        return {0.0, sy};
    }
    const double rad = a * std::numbers::pi / 180.0;
    return {sx * det::cos(rad), sy * det::sin(rad)};
}

constexpr double kCushionTolerancePx = 1e-6;

std::string fmt(double v) {
    std::string s = std::to_string(v);
    return s;
}

} // namespace

std::vector<Body> standard_layout(const PhysicsConfig& config) {
    std::vector<Body> bodies;
    bodies.reserve(kCoinCount);
    const Vec2 c = config.centre();
    const double r = config.coin_radius_px;
    bodies.push_back({kQueenId, BodyKind::Queen, c, {}, false});
    // Inner ring: 6 at 2.5 r, starting straight up (-90 degrees), every 60 degrees.
    for (int i = 0; i < 6; ++i) {
        const BodyKind kind = i % 2 == 0 ? BodyKind::Black : BodyKind::White;
        bodies.push_back({1 + i, kind, c + unit_at_degrees(-90 + 60 * i) * (2.5 * r), {}, false});
    }
    // Outer ring: 12 at 4.5 r, starting at 15 degrees, every 30 degrees.
    for (int i = 0; i < 12; ++i) {
        const BodyKind kind = i % 2 == 0 ? BodyKind::Black : BodyKind::White;
        bodies.push_back({7 + i, kind, c + unit_at_degrees(15 + 30 * i) * (4.5 * r), {}, false});
    }
    return bodies;
}

double baseline_y(const PhysicsConfig& config, Baseline baseline) {
    return baseline == Baseline::Bottom ? config.board_size_px - config.baseline_offset_px
                                        : config.baseline_offset_px;
}

double baseline_x_min(const PhysicsConfig& config) {
    return config.frame_px + config.baseline_end_margin_px + config.striker_radius_px;
}

double baseline_x_max(const PhysicsConfig& config) {
    return config.board_size_px - baseline_x_min(config);
}

Body make_striker(const PhysicsConfig& config, Baseline baseline, const Shot& shot) {
    const double speed = shot.power * config.power_to_speed;
    const Vec2 pos{shot.x_px, baseline_y(config, baseline)};
    const Vec2 vel{speed * det::cos(shot.angle_rad), speed * det::sin(shot.angle_rad)};
    return {kStrikerId, BodyKind::Striker, pos, vel, false};
}

namespace {

// True when every body-by-body check passes, by a pass without early exits: known kinds, ids
// 0 to 63 without repeats, finite numbers, unpocketed centres inside the cushions (with the
// tolerance). False means first_body_error must look (it also handles ids outside 0 to 63).
bool bodies_plainly_valid(const PhysicsConfig& config, std::span<const Body> bodies) {
    std::uint64_t ids = 0;
    bool ok = true;
    for (const Body& b : bodies) {
        const bool small_id = b.id >= 0 && b.id < 64;
        const std::uint64_t bit = small_id ? std::uint64_t{1} << b.id : 0;
        const double r = config.radius(b.kind);
        const double lo = config.cushion_min(r) - kCushionTolerancePx;
        const double hi = config.cushion_max(r) + kCushionTolerancePx;
        const bool inside =
            b.pos_px.x >= lo && b.pos_px.x <= hi && b.pos_px.y >= lo && b.pos_px.y <= hi;
        ok &= small_id & ((ids & bit) == 0) & (b.kind <= BodyKind::Striker) &
              std::isfinite(b.vel_px_s.x) & std::isfinite(b.vel_px_s.y) &
              std::isfinite(b.pos_px.x) & std::isfinite(b.pos_px.y) & (b.pocketed || inside);
        ids |= bit;
    }
    return ok;
}

// The first body-by-body problem, in the order documented for validate_scene.
std::optional<SceneError> first_body_error(const PhysicsConfig& config,
                                           std::span<const Body> bodies) {
    std::uint64_t small_ids = 0; // bit id set: an earlier body has this id (ids 0 to 63)
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        const std::string_view kind = to_string(b.kind);
        if (kind == "unknown") {
            return SceneError{"bad_kind", b.id, "kind",
                              "body " + std::to_string(b.id) + " has an unknown kind"};
        }
        bool duplicate = false;
        if (b.id >= 0 && b.id < 64) {
            const std::uint64_t bit = std::uint64_t{1} << b.id;
            duplicate = (small_ids & bit) != 0;
            small_ids |= bit;
        } else {
            for (std::size_t j = 0; j < i && !duplicate; ++j) {
                duplicate = bodies[j].id == b.id;
            }
        }
        if (duplicate) {
            return SceneError{"duplicate_id", b.id, "id",
                              "body " + std::to_string(b.id) + " appears more than once"};
        }
        const std::pair<const char*, double> fields[] = {{"pos.x", b.pos_px.x},
                                                         {"pos.y", b.pos_px.y},
                                                         {"vel.x", b.vel_px_s.x},
                                                         {"vel.y", b.vel_px_s.y}};
        for (const auto& [field, value] : fields) {
            if (!std::isfinite(value)) {
                return SceneError{"not_finite", b.id, field,
                                  "body " + std::to_string(b.id) + " has a non-finite " + field};
            }
        }
    }
    for (const Body& b : bodies) {
        if (b.pocketed) {
            continue;
        }
        const double r = config.radius(b.kind);
        const double lo = config.cushion_min(r);
        const double hi = config.cushion_max(r);
        const std::pair<const char*, double> axes[] = {{"pos.x", b.pos_px.x},
                                                       {"pos.y", b.pos_px.y}};
        for (const auto& [field, value] : axes) {
            // The engine keeps centres inside to rounding (about 1e-13 px); accept up to 1e-6 px
            // outside so that a scene saved after a cushion contact can be simulated again.
            if (value < lo - kCushionTolerancePx || value > hi + kCushionTolerancePx) {
                return SceneError{"outside_cushions", b.id, field,
                                  "body " + std::to_string(b.id) + " has " + field + " = " +
                                      fmt(value) + ", outside the cushions [" + fmt(lo) + ", " +
                                      fmt(hi) + "] for its radius"};
            }
        }
    }
    return std::nullopt;
}

// The first pair of unpocketed bodies that overlap beyond the tolerance, skipping pairs of two
// bodies in known_pairs_ok (see validate_scene).
std::optional<SceneError> first_overlap(const PhysicsConfig& config, std::span<const Body> bodies,
                                        double overlap_tolerance_px, std::uint64_t known_pairs_ok) {
    // Overlaps: the centres and radii of the bodies on the board are gathered once (on the
    // stack for scenes of up to 64 bodies), in input order, so the first overlapping pair found
    // is the same as in a plain double loop over the input. A branch-free pass first asks
    // whether any pair with a body not in known_pairs_ok comes within reach + slack (none does
    // in a valid scene); only then does the ordered search for the first overlap run.
    struct Disc {
        double x, y, r;
        std::size_t index;
        bool known; // one of the known_pairs_ok bodies
    };
    constexpr std::size_t kStackDiscs = 64;
    std::array<Disc, kStackDiscs> stack_discs;
    std::vector<Disc> heap_discs;
    Disc* discs = stack_discs.data();
    if (bodies.size() > kStackDiscs) {
        heap_discs.resize(bodies.size());
        discs = heap_discs.data();
    }
    std::size_t count = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        if (!b.pocketed) {
            const bool known = i < 64 && ((known_pairs_ok >> i) & 1U) != 0;
            discs[count++] = {b.pos_px.x, b.pos_px.y, config.radius(b.kind), i, known};
        }
    }
    // An overlap beyond the tolerance puts the centres closer than reach + slack, px (slack
    // covers a negative tolerance and the rounding of the exact test).
    const double slack = std::max(0.0, -overlap_tolerance_px) + 1e-3;
    bool near_pair = false;
    // Each body not known to be valid against all others (a pair of two such bodies is tested
    // twice, which changes nothing).
    for (std::size_t i = 0; i < count; ++i) {
        const Disc a = discs[i];
        for (std::size_t j = 0; !a.known && j < count; ++j) {
            const double reach = a.r + discs[j].r + slack;
            const double dx = discs[j].x - a.x;
            const double dy = discs[j].y - a.y;
            near_pair |= j != i && dx * dx + dy * dy < reach * reach;
        }
    }
    for (std::size_t i = 0; near_pair && i < count; ++i) {
        const Disc a = discs[i];
        for (std::size_t j = i + 1; j < count; ++j) {
            const double reach = a.r + discs[j].r;
            const Vec2 d{discs[j].x - a.x, discs[j].y - a.y};
            if ((a.known && discs[j].known) || std::fabs(d.x) >= reach || std::fabs(d.y) >= reach) {
                continue; // cheap rejection; exact test below
            }
            const double overlap = reach - length(d);
            if (overlap > overlap_tolerance_px) {
                const Body& first = bodies[a.index];
                const Body& second = bodies[discs[j].index];
                return SceneError{"overlap", second.id, "pos",
                                  "body " + std::to_string(second.id) + " overlaps body " +
                                      std::to_string(first.id) + " by " + fmt(overlap) + " px"};
            }
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<SceneError> validate_scene(const PhysicsConfig& config, std::span<const Body> bodies,
                                         double overlap_tolerance_px) {
    return validate_scene(config, bodies, overlap_tolerance_px, 0);
}

std::optional<SceneError> validate_scene(const PhysicsConfig& config, std::span<const Body> bodies,
                                         double overlap_tolerance_px,
                                         std::uint64_t known_pairs_ok) {
    if (bodies.size() > 64) {
        known_pairs_ok = 0;
    }
    if (!bodies_plainly_valid(config, bodies)) {
        if (auto error = first_body_error(config, bodies)) {
            return error;
        }
    }
    return first_overlap(config, bodies, overlap_tolerance_px, known_pairs_ok);
}

} // namespace carrom
