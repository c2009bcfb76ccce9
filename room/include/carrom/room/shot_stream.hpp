#pragma once
// Turns one shot's recorded trajectory into the snapshot stream: deltas sampled at whatever
// times the caller asks for (the room asks at every change of motion and at the snapshot rate,
// in real time), the physics events due before each snapshot, and keyframes of the last state
// sent. Values are quantised
// to 0.01 px and 0.01 px/s; a body is in a delta when a quantised value changed.

#include "carrom/config.hpp"
#include "carrom/event.hpp"
#include "carrom/proto/server_messages.hpp"
#include "carrom/trajectory.hpp"
#include "carrom/trajectory_cursor.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace carrom::room {

// A keyframe of `bodies`: every unpocketed body in "bodies", every pocketed id in "pocketed".
// Values are sent as given: a board at rest goes out exact (room_state carries the same exact
// board), so a client that simulates the next stroke from it (shot prediction) starts from the
// server's own input; the stream's keyframes mid-shot pass its quantised last state.
proto::Snapshot make_keyframe(std::span<const Body> bodies, std::int64_t seq, int turn, double t_s);

class ShotStream {
public:
    // `trajectory.initial` is the board as clients know it when the shot starts (the striker's
    // velocity is treated as unknown to them, so the first delta carries it).
    ShotStream(const PhysicsConfig& physics, Trajectory trajectory, std::vector<Event> events,
               double end_time_s, int turn);

    struct Step {
        std::vector<proto::Event> events; // physics events with t <= the snapshot's t
        proto::Snapshot snapshot;         // delta since the previous step
        bool finished = false;            // t reached the end of the shot
    };
    // The state at t_s (clamped to [last t, end]) as a delta with sequence number seq.
    Step advance(double t_s, std::int64_t seq);

    // The first instant after the last snapshot, and at or before t_s, where some body's motion
    // changes (a contact, a stop, a pocketing: a trajectory segment starts); nullopt if none.
    // Between two such instants every body follows the damped free motion exactly, so a delta
    // at each of them lets a client draw the shot exactly.
    std::optional<double> next_motion_change(double t_s) const;

    // The last state sent (or the initial one), as a keyframe.
    proto::Snapshot keyframe(std::int64_t seq) const;

    double end_time_s() const { return end_time_s_; }
    double last_t_s() const { return last_t_s_; }

private:
    PhysicsConfig physics_;
    Trajectory trajectory_;
    TrajectoryCursor cursor_; // each tick costs the segments since the previous one
    std::vector<Event> events_;
    std::size_t next_event_ = 0;
    double end_time_s_;
    int turn_;
    double last_t_s_ = 0.0;
    std::vector<Body> last_sent_; // quantised
};

} // namespace carrom::room
