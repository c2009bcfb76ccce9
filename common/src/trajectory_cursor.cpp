#include "carrom/trajectory_cursor.hpp"
#include "carrom/det_math.hpp"

#include <algorithm>
#include <cmath>

namespace carrom {

void TrajectoryCursor::reset(const Trajectory& trajectory) {
    started_ = true;
    last_t_s_ = 0.0;
    next_segment_ = 0;
    base_ = trajectory.initial;
    since_.assign(base_.size(), 0.0);
}

const std::vector<Body>& TrajectoryCursor::at(const PhysicsConfig& config,
                                              const Trajectory& trajectory, double t_s) {
    t_s = std::max(t_s, 0.0);
    if (!started_ || t_s < last_t_s_) {
        reset(trajectory);
    }
    last_t_s_ = t_s;
    const std::vector<Segment>& segments = trajectory.segments;
    for (; next_segment_ < segments.size(); ++next_segment_) {
        const Segment& seg = segments[next_segment_];
        if (seg.t_s > t_s) {
            break; // segments are in time order
        }
        const auto index = static_cast<std::size_t>(seg.index);
        Body& b = base_[index];
        b.pos_px = seg.pos_px;
        b.vel_px_s = seg.vel_px_s;
        b.pocketed = seg.pocketed;
        since_[index] = seg.t_s;
    }
    now_ = base_;
    const double k = config.damping_per_s;
    for (std::size_t i = 0; i < now_.size(); ++i) {
        Body& b = now_[i];
        if (b.pocketed || (b.vel_px_s.x == 0.0 && b.vel_px_s.y == 0.0)) {
            continue;
        }
        const double dt = t_s - since_[i];
        b.pos_px += b.vel_px_s * travel_factor_s(k, dt);
        b.vel_px_s *= det::exp(-k * dt);
    }
    return now_;
}

} // namespace carrom
