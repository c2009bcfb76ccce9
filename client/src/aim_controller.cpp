#include "carrom/client/aim_controller.hpp"

#include "carrom/rules/placement.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

double clamp_baseline_x(const PhysicsConfig& config, double x_px) {
    if (!std::isfinite(x_px)) {
        return config.centre().x;
    }
    return std::clamp(x_px, baseline_x_min(config), baseline_x_max(config));
}

Vec2 baseline_point(const PhysicsConfig& config, rules::Side side, double along_px) {
    return rules::striker_for(config, side, Shot{along_px, 0.0, 0.0}).pos_px;
}

double along_baseline(rules::Side side, Vec2 p) {
    return side == rules::Side::Bottom || side == rules::Side::Top ? p.x : p.y;
}

double across_baseline(const PhysicsConfig& config, rules::Side side, Vec2 p) {
    const Vec2 on_line = baseline_point(config, side, along_baseline(side, p));
    return length(p - on_line);
}

double power_from_drag(const PhysicsConfig& config, const AimConfig& aim, double drag_px) {
    if (!(drag_px >= aim.dead_zone_px)) {
        return 0.0;
    }
    const double span = aim.full_power_drag_px - aim.dead_zone_px;
    const double fraction = std::min((drag_px - aim.dead_zone_px) / span, 1.0);
    return fraction * config.max_power;
}

Placement check_placement(const PhysicsConfig& config, Vec2 striker_px,
                          std::span<const BodyState> bodies) {
    for (const BodyState& b : bodies) {
        if (b.pocketed || b.kind == BodyKind::Striker) {
            continue;
        }
        const double min_d = config.striker_radius_px + config.radius(b.kind);
        if (length_squared(b.pos_px - striker_px) < min_d * min_d) {
            return {false, b.id};
        }
    }
    return {};
}

AimController::AimController(const PhysicsConfig& config, const AimConfig& aim)
    : config_(config), aim_(aim) {}

void AimController::begin_turn(rules::Side side, double x_px) {
    side_ = side;
    x_px_ = clamp_baseline_x(config_, x_px);
    phase_ = AimPhase::Idle;
    placement_ = {};
    moved_ = false;
}

void AimController::end_turn() {
    phase_ = AimPhase::Inactive;
}

Vec2 AimController::striker_px() const {
    return baseline_point(config_, side_, x_px_);
}

void AimController::set_x(double x_px, std::span<const BodyState> pieces) {
    const double x = clamp_baseline_x(config_, x_px);
    if (x != x_px_) {
        x_px_ = x;
        moved_ = true;
    }
    placement_ = check_placement(config_, striker_px(), pieces);
}

void AimController::pointer_down(Vec2 p, std::span<const BodyState> pieces) {
    if (phase_ != AimPhase::Idle || !is_finite(p)) {
        return;
    }
    pointer_px_ = p;
    const double grab = aim_.grab_factor * config_.striker_radius_px;
    if (length_squared(p - striker_px()) <= grab * grab) {
        phase_ = AimPhase::Pulling;
        placement_ = check_placement(config_, striker_px(), pieces);
    } else if (across_baseline(config_, side_, p) <= aim_.slide_band_px) {
        phase_ = AimPhase::Sliding;
        set_x(along_baseline(side_, p), pieces);
    }
}

void AimController::pointer_move(Vec2 p, std::span<const BodyState> pieces) {
    if (!is_finite(p)) {
        return;
    }
    pointer_px_ = p;
    if (phase_ == AimPhase::Sliding) {
        set_x(along_baseline(side_, p), pieces);
    }
}

std::optional<ShotIntent> AimController::pointer_up(Vec2 p, std::span<const BodyState> pieces) {
    pointer_move(p, pieces);
    if (phase_ == AimPhase::Sliding) {
        phase_ = AimPhase::Idle;
        return std::nullopt;
    }
    if (phase_ != AimPhase::Pulling) {
        return std::nullopt;
    }
    phase_ = AimPhase::Idle;
    placement_ = check_placement(config_, striker_px(), pieces);
    const ShotIntent shot = pending_shot();
    if (!placement_.legal || shot.power <= 0.0) {
        return std::nullopt;
    }
    return shot;
}

void AimController::nudge(int direction, bool coarse, std::span<const BodyState> pieces) {
    if (phase_ != AimPhase::Idle && phase_ != AimPhase::Sliding) {
        return;
    }
    const double step = coarse ? aim_.coarse_step_px : aim_.fine_step_px;
    set_x(x_px_ + step * static_cast<double>(direction), pieces);
}

void AimController::cancel() {
    if (phase_ == AimPhase::Pulling || phase_ == AimPhase::Sliding) {
        phase_ = AimPhase::Idle;
    }
}

ShotIntent AimController::pending_shot() const {
    const Vec2 pull = striker_px() - pointer_px_;
    ShotIntent shot;
    shot.x_px = x_px_;
    shot.angle_rad = std::atan2(pull.y, pull.x);
    shot.power = power_from_drag(config_, aim_, length(pull));
    return shot;
}

double AimController::power_fraction() const {
    return config_.max_power > 0.0 ? pending_shot().power / config_.max_power : 0.0;
}

bool AimController::take_moved() {
    const bool m = moved_;
    moved_ = false;
    return m;
}

} // namespace carrom::client
