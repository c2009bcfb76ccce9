#include "carrom/client/interpolation_buffer.hpp"

#include "carrom/client/hermite.hpp"
#include "carrom/trajectory.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {
namespace {

bool by_id(const BodyState& a, const BodyState& b) {
    return a.id < b.id;
}

const BodyState* find_body(const std::vector<BodyState>& bodies, int id) {
    const auto it = std::lower_bound(bodies.begin(), bodies.end(), id,
                                     [](const BodyState& b, int key) { return b.id < key; });
    return it != bodies.end() && it->id == id ? &*it : nullptr;
}

bool all_at_rest(const std::vector<BodyState>& bodies) {
    return std::all_of(bodies.begin(), bodies.end(), [](const BodyState& b) {
        return b.pocketed || (b.vel_px_s.x == 0.0 && b.vel_px_s.y == 0.0);
    });
}

// Applies a delta: listed bodies replace (or join) the previous ones; the rest keep their place
// and are at rest (a body that moved would have been listed).
std::vector<BodyState> apply_delta(const std::vector<BodyState>& previous,
                                   const std::vector<BodyState>& changed) {
    std::vector<BodyState> out = previous;
    for (BodyState& b : out) {
        b.vel_px_s = {};
    }
    for (const BodyState& c : changed) {
        const auto it = std::lower_bound(out.begin(), out.end(), c, by_id);
        if (it != out.end() && it->id == c.id) {
            *it = c;
        } else {
            out.insert(it, c);
        }
    }
    return out;
}

// Where a body that is at p with velocity v at time t0 is at time t under the damped free motion
// (t may be before t0: the same motion run backwards).
Vec2 free_motion(Vec2 p, Vec2 v, double damping_per_s, double dt_s) {
    return p + v * travel_factor_s(damping_per_s, dt_s);
}

RenderedBody rendered(const BodyState& b, Vec2 pos) {
    RenderedBody r;
    r.id = b.id;
    r.kind = b.kind;
    r.pos_px = pos;
    return r;
}

} // namespace

InterpolationBuffer::InterpolationBuffer(const BoardGeometry& geometry,
                                         const InterpolationConfig& config)
    : geometry_(geometry), config_(config) {}

void InterpolationBuffer::set_motion(double damping_per_s, bool every_change_sent) {
    config_.damping_per_s = damping_per_s;
    every_change_sent_ = every_change_sent;
}

void InterpolationBuffer::clear() {
    frames_.clear();
    falls_.clear();
}

double InterpolationBuffer::newest_time() const {
    return frames_.empty() ? 0.0 : frames_.back().time_s;
}

double InterpolationBuffer::oldest_time() const {
    return frames_.empty() ? 0.0 : frames_.front().time_s;
}

std::uint64_t InterpolationBuffer::newest_seq() const {
    return frames_.empty() ? 0 : frames_.back().seq;
}

const std::vector<BodyState>* InterpolationBuffer::newest_state() const {
    return frames_.empty() ? nullptr : &frames_.back().bodies;
}

bool InterpolationBuffer::push(const Snapshot& snapshot) {
    if (!std::isfinite(snapshot.time_s)) {
        return false;
    }
    if (!frames_.empty()) {
        const Frame& last = frames_.back();
        if (snapshot.seq <= last.seq) {
            return false; // duplicate or reordered
        }
        if (snapshot.time_s < last.time_s) {
            if (!snapshot.keyframe) {
                return false;
            }
            clear(); // the server's clock restarted (a new match): start over
        }
    }
    if (frames_.empty() && !snapshot.keyframe) {
        return false; // a delta needs a state to apply to
    }
    Frame frame;
    frame.seq = snapshot.seq;
    frame.time_s = snapshot.time_s;
    if (snapshot.keyframe) {
        frame.bodies = snapshot.bodies;
        std::sort(frame.bodies.begin(), frame.bodies.end(), by_id);
    } else {
        std::vector<BodyState> changed = snapshot.bodies;
        std::sort(changed.begin(), changed.end(), by_id);
        frame.bodies = apply_delta(frames_.back().bodies, changed);
    }
    frame.at_rest = all_at_rest(frame.bodies);
    if (!frames_.empty()) {
        record_falls(frames_.back(), frame);
        if (frame.time_s == frames_.back().time_s) {
            frames_.pop_back(); // same instant, newer data (e.g. the keyframe ending a shot)
        }
    }
    frames_.push_back(std::move(frame));
    trim();
    return true;
}

void InterpolationBuffer::record_falls(const Frame& before, const Frame& after) {
    const double dt = after.time_s - before.time_s;
    for (const BodyState& b : after.bodies) {
        const BodyState* a = find_body(before.bodies, b.id);
        if (!b.pocketed || a == nullptr || a->pocketed) {
            continue;
        }
        PocketFall fall;
        fall.id = b.id;
        fall.kind = b.kind;
        if (every_change_sent_) {
            // The pocketing is itself a change of motion: it happened at after's instant, and
            // the body got there along the free motion from before.
            fall.start_s = after.time_s;
            fall.from_px = free_motion(a->pos_px, a->vel_px_s, config_.damping_per_s, dt);
            fall.from_vel_px_s = a->vel_px_s * std::exp(-config_.damping_per_s * dt);
        } else {
            fall.start_s = before.time_s;
            fall.from_px = a->pos_px;
            fall.from_vel_px_s = a->vel_px_s;
        }
        const Vec2 heading = a->pos_px + a->vel_px_s * dt;
        fall.pocket_px =
            geometry_.pockets[static_cast<std::size_t>(nearest_pocket(geometry_, heading))];
        falls_.push_back(fall);
    }
}

void InterpolationBuffer::trim() {
    const double keep_from = frames_.back().time_s - config_.history_s;
    while (frames_.size() > 2 && frames_[1].time_s <= keep_from) {
        frames_.pop_front();
    }
    const double fall_from = frames_.front().time_s - config_.pocket_anim_s;
    std::erase_if(falls_, [&](const PocketFall& f) { return f.start_s < fall_from; });
}

std::optional<RenderedBody> InterpolationBuffer::falling_body(int id, double t_s) const {
    const PocketFall* fall = nullptr;
    for (const PocketFall& f : falls_) {
        if (f.id == id && f.start_s <= t_s && (fall == nullptr || f.start_s > fall->start_s)) {
            fall = &f;
        }
    }
    if (fall == nullptr) {
        return std::nullopt;
    }
    const double elapsed = t_s - fall->start_s;
    const double u = elapsed / config_.pocket_anim_s;
    if (u >= 1.0) {
        return std::nullopt;
    }
    // The piece keeps its speed towards the pocket centre but gets there by the end at the latest.
    const Vec2 to_pocket = fall->pocket_px - fall->from_px;
    const double dist = length(to_pocket);
    const double eased = u * u * (3.0 - 2.0 * u);
    const double by_speed = dist > 0.0 ? length(fall->from_vel_px_s) * elapsed / dist : 1.0;
    const double progress = std::min(1.0, std::max(eased, by_speed));
    RenderedBody r;
    r.id = id;
    r.kind = fall->kind;
    r.pos_px = fall->from_px + to_pocket * progress;
    r.scale = 1.0 - (1.0 - config_.pocket_end_scale) * u;
    r.alpha = 1.0 - u;
    r.falling = true;
    return r;
}

std::optional<RenderedBody> InterpolationBuffer::body_between(const Frame& a, const Frame& b,
                                                              const BodyState& bb,
                                                              double t_s) const {
    const BodyState* ba = find_body(a.bodies, bb.id);
    if (bb.pocketed) {
        if (every_change_sent_ && ba != nullptr && !ba->pocketed && t_s < b.time_s) {
            // Pocketed at b's instant: until then it moves on freely from a.
            return rendered(
                bb, free_motion(ba->pos_px, ba->vel_px_s, config_.damping_per_s, t_s - a.time_s));
        }
        return falling_body(bb.id, t_s);
    }
    if (ba == nullptr) {
        return rendered(bb, bb.pos_px); // appears with the newer state
    }
    if (ba->pocketed) {
        return std::nullopt; // back on the board from the newer state on
    }
    const double gap = b.time_s - a.time_s;
    if (gap > config_.hold_gap_s && a.at_rest) {
        return rendered(bb, ba->pos_px); // the board rested; the next run starts at b
    }
    const double k = config_.damping_per_s;
    const double tol = config_.free_motion_tolerance_px;
    const double dt_a = t_s - a.time_s;
    // No change of motion between a and b: the free motion from a reaches b.
    if (length(free_motion(ba->pos_px, ba->vel_px_s, k, gap) - bb.pos_px) <= tol) {
        return rendered(bb, free_motion(ba->pos_px, ba->vel_px_s, k, dt_a));
    }
    // One change of motion at an unknown instant c: forwards from a before c, backwards from b
    // after c. With u = e^(-k (t - t_a)) their difference is linear in u,
    //   d(u) = (p_a - p_b) + (v_a - v_b) / k + u (v_b e^(k gap) - v_a) / k,
    // and c is where it vanishes (solved in least squares; accepted when the residual is within
    // the tolerance).
    if (k > 0.0) {
        const Vec2 d0 = ba->pos_px - bb.pos_px + (ba->vel_px_s - bb.vel_px_s) * (1.0 / k);
        const Vec2 w = (bb.vel_px_s * std::exp(k * gap) - ba->vel_px_s) * (1.0 / k);
        const double ww = dot(w, w);
        if (ww > 0.0) {
            const double u = std::clamp(-dot(d0, w) / ww, std::exp(-k * gap), 1.0);
            if (length(d0 + w * u) <= tol) {
                const double change_s = a.time_s - std::log(u) / k;
                return rendered(bb, t_s <= change_s
                                        ? free_motion(ba->pos_px, ba->vel_px_s, k, dt_a)
                                        : free_motion(bb.pos_px, bb.vel_px_s, k, t_s - b.time_s));
            }
        }
    }
    const double s = std::clamp(dt_a / gap, 0.0, 1.0);
    return rendered(bb, hermite(ba->pos_px, ba->vel_px_s, bb.pos_px, bb.vel_px_s, gap, s));
}

std::vector<RenderedBody> InterpolationBuffer::sample(double t_s) const {
    std::vector<RenderedBody> out;
    if (frames_.empty()) {
        return out;
    }
    const auto after = std::upper_bound(frames_.begin(), frames_.end(), t_s,
                                        [](double t, const Frame& f) { return t < f.time_s; });
    if (after == frames_.begin()) {
        for (const BodyState& b : frames_.front().bodies) {
            if (!b.pocketed) {
                out.push_back(rendered(b, b.pos_px));
            }
        }
        return out;
    }
    if (after == frames_.end()) {
        const Frame& last = frames_.back();
        const double ahead = std::min(t_s - last.time_s,
                                      every_change_sent_ ? config_.max_extrapolation_every_change_s
                                                         : config_.max_extrapolation_s);
        for (const BodyState& b : last.bodies) {
            if (!b.pocketed) {
                out.push_back(
                    rendered(b, free_motion(b.pos_px, b.vel_px_s, config_.damping_per_s, ahead)));
            } else if (auto fall = falling_body(b.id, t_s)) {
                out.push_back(*fall);
            }
        }
        return out;
    }
    const Frame& b = *after;
    const Frame& a = *std::prev(after);
    for (const BodyState& bb : b.bodies) {
        if (auto r = body_between(a, b, bb, t_s)) {
            out.push_back(*r);
        }
    }
    return out;
}

} // namespace carrom::client
