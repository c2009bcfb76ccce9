#include "carrom/client/aim_controller.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

double clamp_baseline_x(const PhysicsConfig& config, double x_px) {
    if (!std::isfinite(x_px)) {
        return config.centre().x;
    }
    return std::clamp(x_px, baseline_x_min(config), baseline_x_max(config));
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

void AimController::begin_turn(Baseline baseline, double x_px) {
    baseline_ = baseline;
    x_px_ = clamp_baseline_x(config_, x_px);
    phase_ = AimPhase::Idle;
    placement_ = {};
    moved_ = false;
}

void AimController::end_turn() {
    phase_ = AimPhase::Inactive;
}

Vec2 AimController::striker_px() const {
    return {x_px_, baseline_y(config_, baseline_)};
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
    } else if (std::abs(p.y - baseline_y(config_, baseline_)) <= aim_.slide_band_px) {
        phase_ = AimPhase::Sliding;
        set_x(p.x, pieces);
    }
}

void AimController::pointer_move(Vec2 p, std::span<const BodyState> pieces) {
    if (!is_finite(p)) {
        return;
    }
    pointer_px_ = p;
    if (phase_ == AimPhase::Sliding) {
        set_x(p.x, pieces);
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
