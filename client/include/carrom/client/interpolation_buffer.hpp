#pragma once
// Snapshots in, the board at any server time out. Keeps a short history of full board states
// (deltas are applied onto the previous state) and draws each body between the two states around
// the requested time along the damped free motion p(t) = p0 + v0 (1 - e^(-k dt)) / k when that
// explains both states (no change of motion between them, or exactly one, whose instant it
// solves for), else along a cubic Hermite curve through their positions and velocities; and
// animates a pocketed piece into its pocket (sliding to the pocket centre while it shrinks and
// fades) instead of dropping it. Units: board px, px/s, server match time in s.

#include "carrom/client/board_geometry.hpp"
#include "carrom/client/snapshot.hpp"
#include "carrom/config.hpp"

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

namespace carrom::client {

struct InterpolationConfig {
    double pocket_anim_s = 0.15;       // time a piece takes to vanish into its pocket
    double pocket_end_scale = 0.35;    // its size, relative, at the end of that animation
    double hold_gap_s = 0.25;          // a longer gap after a board at rest is a jump, not a glide
    double max_extrapolation_s = 0.05; // past the newest state, along the free motion
    // the same when the server sends a delta at every change of motion (the free motion past
    // the newest state is then exact until the next delta arrives)
    double max_extrapolation_every_change_s = 0.25;
    double damping_per_s = PhysicsConfig{}.damping_per_s; // k of the free motion, 1/s
    double free_motion_tolerance_px = 0.05; // how closely the free motion must explain a state
    double history_s = 2.0;                 // states older than this behind the newest are dropped
};

struct RenderedBody {
    int id = 0;
    BodyKind kind = BodyKind::Black;
    Vec2 pos_px{};
    double scale = 1.0; // 1 on the board, shrinking while it falls into a pocket
    double alpha = 1.0; // 1 opaque
    bool falling = false;
};

class InterpolationBuffer {
public:
    InterpolationBuffer(const BoardGeometry& geometry, const InterpolationConfig& config = {});

    // Adds a snapshot. A delta needs a previous state to apply to; a snapshot that is older than
    // (or as old as) the newest one is ignored. Returns false if ignored.
    bool push(const Snapshot& snapshot);
    // The server's motion model (room_state "motion"): k, and whether it sends a delta at the
    // instant of every change of motion (contact, stop, pocketing).
    void set_motion(double damping_per_s, bool every_change_sent);
    // Forgets everything (a new match, a resume with a fresh keyframe follows).
    void clear();

    bool empty() const { return frames_.empty(); }
    double newest_time() const;
    double oldest_time() const;
    std::uint64_t newest_seq() const;
    // The newest full state (for placement checks and the HUD).
    const std::vector<BodyState>* newest_state() const;

    // The bodies to draw at server time t_s, sorted by id. Before the oldest state: the oldest;
    // after the newest: the newest, extrapolated for at most max_extrapolation_s.
    std::vector<RenderedBody> sample(double t_s) const;

private:
    struct Frame {
        std::uint64_t seq = 0;
        double time_s = 0.0;
        std::vector<BodyState> bodies; // sorted by id
        bool at_rest = true;
    };
    struct PocketFall {
        int id = 0;
        BodyKind kind = BodyKind::Black;
        double start_s = 0.0; // time of the last state before the piece was seen pocketed
        Vec2 from_px{};
        Vec2 from_vel_px_s{};
        Vec2 pocket_px{};
    };

    void record_falls(const Frame& before, const Frame& after);
    void trim();
    std::optional<RenderedBody> body_between(const Frame& a, const Frame& b, const BodyState& bb,
                                             double t_s) const;
    std::optional<RenderedBody> falling_body(int id, double t_s) const;

    BoardGeometry geometry_;
    InterpolationConfig config_;
    std::deque<Frame> frames_;
    std::vector<PocketFall> falls_;
    bool every_change_sent_ = false;
};

} // namespace carrom::client
