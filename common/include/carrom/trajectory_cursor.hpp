#pragma once
// The state of a recorded trajectory at non-decreasing times, each in O(segments passed since the
// previous call + bodies): the cursor keeps the index of the next segment and the state the
// segments before it left. Its result is bit-identical to state_at (the same operations in the
// same order). A time earlier than the previous one starts again from the first segment.

#include "carrom/body.hpp"
#include "carrom/config.hpp"
#include "carrom/trajectory.hpp"

#include <cstddef>
#include <vector>

namespace carrom {

class TrajectoryCursor {
public:
    // The state of every body at t_s (clamped to t >= 0), same order as trajectory.initial.
    // `trajectory` must be the same one on every call (the cursor keeps no pointer to it, so
    // the owner of both may move them). The reference is valid until the next call.
    const std::vector<Body>& at(const PhysicsConfig& config, const Trajectory& trajectory,
                                double t_s);

private:
    void reset(const Trajectory& trajectory);

    bool started_ = false;
    double last_t_s_ = 0.0;
    std::size_t next_segment_ = 0;
    std::vector<Body> base_;    // the bodies as the segments before next_segment_ left them
    std::vector<double> since_; // time each body's current segment began, s
    std::vector<Body> now_;     // the last result
};

} // namespace carrom
