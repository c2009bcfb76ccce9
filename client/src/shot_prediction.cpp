#include "carrom/client/shot_prediction.hpp"

#include "carrom/exact_engine.hpp"
#include "carrom/rules/placement.hpp"

#include <algorithm>
#include <cmath>

namespace carrom::client {

ShotPrediction::ShotPrediction(const PhysicsConfig& physics, const PredictionConfig& config)
    : physics_(physics), config_(config) {}

bool ShotPrediction::start(int turn, std::span<const BodyState> board, rules::Side side,
                           const Shot& shot, double offset_s) {
    active_ = false;
    std::vector<Body> bodies;
    for (const BodyState& b : board) {
        if (b.id != kStrikerId) {
            bodies.push_back({b.id, b.kind, b.pos_px, {}, b.pocketed});
        }
    }
    std::sort(bodies.begin(), bodies.end(),
              [](const Body& a, const Body& b) { return a.id < b.id; });
    // The striker exactly as the server's rules place it (rules::play_shot).
    bodies.push_back(rules::striker_for(physics_, side, shot));
    SimOptions options;
    options.record_events = true;
    options.record_trajectory = true;
    SimulateResult run = simulate_exact(physics_, bodies, options);
    if (run.error) {
        return false;
    }
    active_ = true;
    confirmed_ = false;
    server_done_ = false;
    turn_ = turn;
    offset_s_ = offset_s;
    trajectory_ = std::move(run.result.trajectory);
    events_ = std::move(run.result.events);
    claimed_.assign(events_.size(), false);
    blends_.clear();
    ++stats_.strokes;
    stats_.stroke_max_difference_px = 0.0;
    return true;
}

Vec2 ShotPrediction::drawn_offset(const Blend& blend, double local_s) const {
    Vec2 offset = blend.target;
    for (const Fade& f : blend.fades) {
        const double u = (local_s - f.start_local_s) / config_.blend_s;
        if (u < 1.0) {
            offset -= f.step * (1.0 - std::max(u, 0.0));
        }
    }
    return offset;
}

void ShotPrediction::confirm(std::span<const BodyState> server, double shot_t_s, double local_s) {
    if (!active_) {
        return;
    }
    confirmed_ = true;
    const std::vector<Body> predicted = state_at(physics_, trajectory_, shot_t_s);
    for (const BodyState& s : server) {
        const auto p = std::find_if(predicted.begin(), predicted.end(),
                                    [&](const Body& b) { return b.id == s.id; });
        if (p == predicted.end()) {
            continue;
        }
        const Vec2 difference = s.pos_px - p->pos_px;
        const double size = (s.pocketed && p->pocketed) ? 0.0 : length(difference);
        Blend& blend = blends_[s.id];
        blend.server_pocketed = s.pocketed;
        stats_.max_difference_px = std::max(stats_.max_difference_px, size);
        stats_.stroke_max_difference_px = std::max(stats_.stroke_max_difference_px, size);
        if ((size > config_.correction_px || s.pocketed != p->pocketed) && !blend.counted) {
            blend.counted = true;
            ++stats_.corrections;
        }
        if (s.pocketed || p->pocketed) {
            continue;
        }
        std::erase_if(blend.fades,
                      [&](const Fade& f) { return local_s - f.start_local_s >= config_.blend_s; });
        const Vec2 step = difference - blend.target;
        if (length(step) > config_.step_px) {
            blend.fades.push_back({step, local_s});
        }
        blend.target = difference;
    }
}

bool ShotPrediction::blending(double local_s) const {
    return std::any_of(blends_.begin(), blends_.end(), [&](const auto& entry) {
        return std::any_of(
            entry.second.fades.begin(), entry.second.fades.end(),
            [&](const Fade& f) { return local_s - f.start_local_s < config_.blend_s; });
    });
}

std::vector<RenderedBody> ShotPrediction::draw(double t_s, double local_s,
                                               const std::vector<RenderedBody>* server) const {
    std::vector<RenderedBody> out;
    if (server != nullptr) {
        // The server's states reach t_s: its sample, less what is left of each blend.
        out = *server;
        for (RenderedBody& b : out) {
            const auto it = blends_.find(b.id);
            if (it != blends_.end() && !b.falling) {
                const Vec2 rest = drawn_offset(it->second, local_s) - it->second.target;
                if (rest != Vec2{}) {
                    b.pos_px += rest;
                }
            }
        }
        return out;
    }
    for (const Body& p : state_at(physics_, trajectory_, t_s - offset_s_)) {
        const auto it = blends_.find(p.id);
        if (p.pocketed || (it != blends_.end() && it->second.server_pocketed)) {
            continue;
        }
        RenderedBody b;
        b.id = p.id;
        b.kind = p.kind;
        b.pos_px = p.pos_px;
        if (it != blends_.end()) {
            b.pos_px += drawn_offset(it->second, local_s);
        }
        out.push_back(b);
    }
    return out;
}

std::vector<SoundCue> ShotPrediction::cues() const {
    std::vector<SoundCue> out;
    for (const Event& e : events_) {
        const double t = offset_s_ + e.t_s;
        switch (e.kind) {
        case EventKind::Collision:
            out.push_back({t, SoundKind::Click, loudness_from_impulse(e.impulse)});
            break;
        case EventKind::Cushion:
            out.push_back({t, SoundKind::Cushion, 0.8 * loudness_from_impulse(e.impulse)});
            break;
        case EventKind::Pocket:
            out.push_back({t, SoundKind::Pocket, 1.0});
            break;
        case EventKind::Stop:
            break;
        }
    }
    std::erase_if(out, [](const SoundCue& c) { return c.volume <= 0.0; });
    return out;
}

bool ShotPrediction::claim_cue(int turn, SoundKind kind, double t_s) {
    if (turn != turn_) {
        return false;
    }
    for (std::size_t i = 0; i < events_.size(); ++i) {
        const Event& e = events_[i];
        const SoundKind k = e.kind == EventKind::Collision ? SoundKind::Click
                            : e.kind == EventKind::Cushion ? SoundKind::Cushion
                                                           : SoundKind::Pocket;
        if (!claimed_[i] && e.kind != EventKind::Stop && k == kind &&
            std::abs(e.t_s - t_s) <= config_.cue_tolerance_s) {
            claimed_[i] = true;
            return true;
        }
    }
    return false;
}

} // namespace carrom::client
