#include "carrom/rules/placement.hpp"
#include "carrom/det_math.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace carrom::rules {
namespace {

// Returned pieces are placed this far beyond touching, so float rounding never makes them
// overlap, px.
constexpr double kClearancePx = 1e-6;

struct Disc {
    Vec2 centre;
    double reach; // sum of radii: a centre closer than this overlaps
};

bool is_free(Vec2 p, const std::vector<Disc>& discs, double lo, double hi) {
    if (!is_finite(p) || p.x < lo || p.x > hi || p.y < lo || p.y > hi) {
        return false;
    }
    for (const Disc& d : discs) {
        if (length_squared(p - d.centre) < d.reach * d.reach) {
            return false;
        }
    }
    return true;
}

// The two points at distance ra + eps from a and rb + eps from b, when they exist.
int circle_intersections(const Disc& a, const Disc& b, Vec2 out[2]) {
    const double ra = a.reach + kClearancePx;
    const double rb = b.reach + kClearancePx;
    const Vec2 ab = b.centre - a.centre;
    const double d = length(ab);
    if (d <= 0.0 || d > ra + rb || d < std::fabs(ra - rb)) {
        return 0;
    }
    const double along = (ra * ra - rb * rb + d * d) / (2.0 * d);
    const double h = std::sqrt(std::fmax(ra * ra - along * along, 0.0));
    const Vec2 u = ab * (1.0 / d);
    const Vec2 n{-u.y, u.x};
    const Vec2 base = a.centre + u * along;
    out[0] = base + n * h;
    out[1] = base - n * h;
    return 2;
}

struct Best {
    Vec2 pos{};
    double dist2 = std::numeric_limits<double>::infinity();
    void offer(Vec2 p, Vec2 centre, const std::vector<Disc>& discs, double lo, double hi) {
        const double d2 = length_squared(p - centre);
        if (d2 < dist2 && is_free(p, discs, lo, hi)) {
            pos = p;
            dist2 = d2;
        }
    }
};

// Never reached with 19 pieces on a standard board; keeps the function total.
Vec2 grid_fallback(Vec2 centre, const std::vector<Disc>& discs, double lo, double hi) {
    Best best;
    for (double y = lo; y <= hi; y += 1.0) {
        for (double x = lo; x <= hi; x += 1.0) {
            best.offer({x, y}, centre, discs, lo, hi);
        }
    }
    return std::isfinite(best.dist2) ? best.pos : centre;
}

} // namespace

Body striker_for(const PhysicsConfig& physics, Side side, const Shot& shot) {
    Body striker = make_striker(physics, Baseline::Bottom, shot);
    const double near = physics.baseline_offset_px;
    const double far = physics.board_size_px - physics.baseline_offset_px;
    switch (side) {
    case Side::Bottom:
        striker.pos_px = {shot.x_px, far};
        break;
    case Side::Top:
        striker.pos_px = {shot.x_px, near};
        break;
    case Side::Left:
        striker.pos_px = {near, shot.x_px};
        break;
    case Side::Right:
        striker.pos_px = {far, shot.x_px};
        break;
    }
    return striker;
}

std::optional<RuleError> check_placement(const MatchState& state, int seat, const Shot& shot) {
    const PhysicsConfig& physics = state.physics;
    if (seat < 0 || seat >= static_cast<int>(state.seats.size())) {
        return RuleError{RuleErrorCode::InvalidSeat, "seat",
                         "There is no seat " + std::to_string(seat) + "."};
    }
    if (!std::isfinite(shot.x_px)) {
        return RuleError{RuleErrorCode::XNotFinite, "shot.x",
                         "The striker position is not a finite number."};
    }
    const double lo = baseline_x_min(physics);
    const double hi = baseline_x_max(physics);
    if (shot.x_px < lo || shot.x_px > hi) {
        return RuleError{RuleErrorCode::XOutOfRange, "shot.x",
                         "The striker must be placed on the baseline between " +
                             std::to_string(lo) + " and " + std::to_string(hi) + " px."};
    }
    const Body striker =
        striker_for(physics, state.seats[static_cast<std::size_t>(seat)].side, shot);
    for (const Body& body : state.bodies) {
        if (body.pocketed) {
            continue;
        }
        const double reach = physics.striker_radius_px + physics.radius(body.kind);
        if (length_squared(body.pos_px - striker.pos_px) < reach * reach) {
            return RuleError{RuleErrorCode::StrikerOverlaps, "shot.x",
                             "The striker would overlap piece " + std::to_string(body.id) +
                                 "; place it where it touches no piece."};
        }
    }
    if (!std::isfinite(shot.angle_rad)) {
        return RuleError{RuleErrorCode::AngleNotFinite, "shot.angle",
                         "The angle is not a finite number."};
    }
    if (!std::isfinite(shot.power)) {
        return RuleError{RuleErrorCode::PowerNotFinite, "shot.power",
                         "The power is not a finite number."};
    }
    if (shot.power < 0.0 || shot.power > physics.max_power) {
        return RuleError{RuleErrorCode::PowerOutOfRange, "shot.power",
                         "The power must be in [0, " + std::to_string(physics.max_power) + "]."};
    }
    return std::nullopt;
}

std::optional<Shot> nearest_legal_shot(const MatchState& state, int seat, const Shot& shot) {
    if (seat < 0 || seat >= static_cast<int>(state.seats.size())) {
        return std::nullopt;
    }
    const PhysicsConfig& physics = state.physics;
    const double lo = baseline_x_min(physics);
    const double hi = baseline_x_max(physics);
    Shot legal = shot;
    legal.x_px = std::isfinite(shot.x_px) ? std::clamp(shot.x_px, lo, hi) : 0.5 * (lo + hi);
    legal.power = std::isfinite(shot.power) ? std::clamp(shot.power, 0.0, physics.max_power) : 0.0;
    const Side side = state.seats[static_cast<std::size_t>(seat)].side;
    const auto placed = [&](double x) {
        Shot s = legal;
        s.x_px = x;
        if (!std::isfinite(shot.angle_rad)) {
            const Vec2 to_centre = physics.centre() - striker_for(physics, side, s).pos_px;
            s.angle_rad = det::atan2(to_centre.y, to_centre.x);
        }
        return s;
    };
    constexpr double kStepPx = 0.125;
    const double reach = std::fmax(legal.x_px - lo, hi - legal.x_px);
    for (int i = 0; i * kStepPx <= reach; ++i) {
        for (const double x : {legal.x_px - i * kStepPx, legal.x_px + i * kStepPx}) {
            if (x < lo || x > hi) {
                continue;
            }
            const Shot candidate = placed(x);
            if (!check_placement(state, seat, candidate)) {
                return candidate;
            }
        }
    }
    return std::nullopt;
}

Vec2 free_spot_near_centre(const PhysicsConfig& physics, std::span<const Body> bodies,
                           double radius_px) {
    std::vector<Disc> discs;
    for (const Body& body : bodies) {
        if (!body.pocketed) {
            discs.push_back({body.pos_px, radius_px + physics.radius(body.kind)});
        }
    }
    const Vec2 centre = physics.centre();
    const double lo = physics.cushion_min(radius_px);
    const double hi = physics.cushion_max(radius_px);
    Best best;
    best.offer(centre, centre, discs, lo, hi);
    if (best.dist2 == 0.0) {
        return centre;
    }
    for (const Disc& d : discs) {
        const Vec2 away = centre - d.centre;
        const double len = length(away);
        const Vec2 dir = len > 0.0 ? away * (1.0 / len) : Vec2{0.0, -1.0};
        best.offer(d.centre + dir * (d.reach + kClearancePx), centre, discs, lo, hi);
    }
    for (std::size_t i = 0; i < discs.size(); ++i) {
        for (std::size_t j = i + 1; j < discs.size(); ++j) {
            Vec2 points[2];
            const int n = circle_intersections(discs[i], discs[j], points);
            for (int k = 0; k < n; ++k) {
                best.offer(points[k], centre, discs, lo, hi);
            }
        }
    }
    return std::isfinite(best.dist2) ? best.pos : grid_fallback(centre, discs, lo, hi);
}

} // namespace carrom::rules
