#include "carrom/room/shot_stream.hpp"

#include "carrom/proto/codec.hpp"

#include <algorithm>

namespace carrom::room {

namespace {

Body quantised(Body body) {
    body.pos_px = {proto::quantise(body.pos_px.x), proto::quantise(body.pos_px.y)};
    body.vel_px_s = {proto::quantise(body.vel_px_s.x), proto::quantise(body.vel_px_s.y)};
    return body;
}

std::optional<proto::Event> to_proto_event(const Event& e, int turn) {
    switch (e.kind) {
    case EventKind::Collision:
        return proto::CollisionEvent{turn, e.t_s, e.a, e.b, e.impulse};
    case EventKind::Cushion:
        return proto::CushionEvent{turn, e.t_s, e.a, e.b, e.impulse};
    case EventKind::Pocket:
        return proto::PocketEvent{turn, e.t_s, e.a, e.b};
    case EventKind::Stop:
        return std::nullopt;
    }
    return std::nullopt;
}

} // namespace

proto::Snapshot make_keyframe(std::span<const Body> bodies, std::int64_t seq, int turn,
                              double t_s) {
    proto::Snapshot snap;
    snap.seq = seq;
    snap.turn = turn;
    snap.t_s = t_s;
    snap.keyframe = true;
    for (const Body& b : bodies) {
        if (b.pocketed) {
            snap.pocketed.push_back(b.id);
        } else {
            snap.bodies.push_back({b.id, b.pos_px, b.vel_px_s});
        }
    }
    return snap;
}

ShotStream::ShotStream(const PhysicsConfig& physics, Trajectory trajectory,
                       std::vector<Event> events, double end_time_s, int turn)
    : physics_(physics), trajectory_(std::move(trajectory)), events_(std::move(events)),
      end_time_s_(end_time_s), turn_(turn) {
    last_sent_.reserve(trajectory_.initial.size());
    for (Body body : trajectory_.initial) {
        body.vel_px_s = {};
        last_sent_.push_back(quantised(body));
    }
}

ShotStream::Step ShotStream::advance(double t_s, std::int64_t seq) {
    Step step;
    const double t = std::clamp(t_s, last_t_s_, end_time_s_);
    last_t_s_ = t;
    step.finished = t >= end_time_s_;
    while (next_event_ < events_.size() && (events_[next_event_].t_s <= t || step.finished)) {
        if (auto e = to_proto_event(events_[next_event_], turn_)) {
            step.events.push_back(std::move(*e));
        }
        ++next_event_;
    }
    step.snapshot.seq = seq;
    step.snapshot.turn = turn_;
    step.snapshot.t_s = t;
    const std::vector<Body>& now = cursor_.at(physics_, trajectory_, t);
    for (std::size_t i = 0; i < now.size() && i < last_sent_.size(); ++i) {
        const Body b = quantised(now[i]);
        Body& last = last_sent_[i];
        if (b.pocketed) {
            if (!last.pocketed) {
                step.snapshot.pocketed.push_back(b.id);
            }
        } else if (last.pocketed || b.pos_px != last.pos_px || b.vel_px_s != last.vel_px_s) {
            step.snapshot.bodies.push_back({b.id, b.pos_px, b.vel_px_s});
        }
        last = b;
    }
    return step;
}

std::optional<double> ShotStream::next_motion_change(double t_s) const {
    // Segments are in time order; the cursor has applied every segment at or before last_t_s_.
    const std::vector<Segment>& segments = trajectory_.segments;
    const auto after = std::upper_bound(segments.begin(), segments.end(), last_t_s_,
                                        [](double t, const Segment& seg) { return t < seg.t_s; });
    if (after == segments.end() || after->t_s > std::min(t_s, end_time_s_)) {
        return std::nullopt;
    }
    return after->t_s;
}

proto::Snapshot ShotStream::keyframe(std::int64_t seq) const {
    return make_keyframe(last_sent_, seq, turn_, last_t_s_);
}

} // namespace carrom::room
