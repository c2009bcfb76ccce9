#include "carrom/first_contact.hpp"

#include <cmath>
#include <cstddef>

namespace carrom {

namespace {

// Index of the body with `id` in `bodies`, -1 if none.
int index_of_id(std::span<const Body> bodies, int id) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (bodies[i].id == id) {
            return static_cast<int>(i);
        }
    }
    return -1;
}

// The velocity of body `index` as the trajectory has it just after t_s: its last segment that
// starts at or before t_s (zero if it has none: it never moved).
Vec2 velocity_after(const Trajectory& trajectory, int index, double t_s) {
    Vec2 vel{};
    for (const Segment& s : trajectory.segments) {
        if (s.t_s > t_s) {
            break;
        }
        if (s.index == index) {
            vel = s.pocketed ? Vec2{} : s.vel_px_s;
        }
    }
    return vel;
}

} // namespace

std::optional<FirstContact> first_contact(ExactEngine& engine, std::span<const Body> bodies) {
    int striker = -1;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const Body& b = bodies[i];
        if (b.kind == BodyKind::Striker && !b.pocketed && length_squared(b.vel_px_s) > 0.0) {
            striker = b.id;
            break;
        }
    }
    if (striker < 0) {
        return std::nullopt;
    }
    SimOptions options;
    options.record_events = true;
    options.record_trajectory = true;
    const ExactEngine::Outcome run = engine.run(bodies, options);
    if (run.error || run.result == nullptr) {
        return std::nullopt;
    }
    const SimResult& result = *run.result;
    for (const Event& e : result.events) {
        if (e.kind != EventKind::Collision || (e.a != striker && e.b != striker)) {
            continue;
        }
        FirstContact contact;
        contact.piece_id = e.a == striker ? e.b : e.a;
        contact.t_s = e.t_s;
        const int piece_index = index_of_id(bodies, contact.piece_id);
        const int striker_index = index_of_id(bodies, striker);
        const std::vector<Body> at_contact = state_at(engine.config(), result.trajectory, e.t_s);
        contact.striker_px = at_contact[static_cast<std::size_t>(striker_index)].pos_px;
        contact.piece_px = at_contact[static_cast<std::size_t>(piece_index)].pos_px;
        contact.piece_vel_px_s = velocity_after(result.trajectory, piece_index, e.t_s);
        const double speed = length(contact.piece_vel_px_s);
        if (speed > 0.0) {
            contact.piece_direction = contact.piece_vel_px_s * (1.0 / speed);
        }
        return contact;
    }
    return std::nullopt;
}

} // namespace carrom
