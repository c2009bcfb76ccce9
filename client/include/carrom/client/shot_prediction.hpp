#pragma once
// The shooter's own stroke, simulated on release with the exact engine (common/) from the board
// the client holds, so that it is drawn at once instead of a round trip later. The server's
// snapshots of the stroke take over: for each body the difference between the server's state and
// the predicted one at the same shot time is measured on every snapshot, and the drawn offset
// moves linearly to it within blend_s: each change of a difference over step_px is faded in over
// blend_s, smaller ones (quantisation, a slow drift) at once. A body whose difference exceeds
// correction_px counts as a correction. Once the server's states reach the rendered time and every
// blend is complete, what is drawn is the server's state exactly. Times: continuous client timeline
// (s) for the board, local clock (s) for the blends.

#include "carrom/body.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/snapshot.hpp"
#include "carrom/client/sound_synth.hpp"
#include "carrom/config.hpp"
#include "carrom/event.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"
#include "carrom/trajectory.hpp"

#include <map>
#include <span>
#include <vector>

namespace carrom::client {

struct PredictionConfig {
    double blend_s = 0.1;           // time the drawn state takes to reach the server's
    double correction_px = 0.5;     // a larger difference counts as a correction
    double cue_tolerance_s = 0.005; // a server sound cue this close to a predicted one is the same
    double step_px = 0.1;           // smaller changes of a difference are drawn at once
};

struct PredictionStats {
    int strokes = 0;                // strokes predicted
    int corrections = 0;            // bodies (once per stroke) whose difference exceeded the limit
    double max_difference_px = 0.0; // the largest difference seen
    double stroke_max_difference_px = 0.0; // the largest in the last stroke predicted
};

class ShotPrediction {
public:
    explicit ShotPrediction(const PhysicsConfig& physics, const PredictionConfig& config = {});

    // Simulates the stroke of `turn` from `board` (the board at rest; a striker in it is
    // replaced) with the striker placed as the server places it for `side`; its t = 0 is
    // offset_s on the continuous timeline. False (and nothing predicted) when the engine refuses
    // the scene (the server will refuse the shot as well).
    bool start(int turn, std::span<const BodyState> board, rules::Side side, const Shot& shot,
               double offset_s);
    // Stops drawing the prediction at the end of the stroke (its sounds stay claimable).
    void stop() { active_ = false; }
    // Forgets the prediction (a refused shot, a reset).
    void drop() {
        active_ = false;
        turn_ = -1;
    }

    bool active() const { return active_; }
    int turn() const { return turn_; }
    double offset_s() const { return offset_s_; }
    // A server snapshot of the stroke has arrived.
    bool confirmed() const { return confirmed_; }
    // The server's last keyframe of the stroke has arrived.
    bool server_done() const { return server_done_; }
    void mark_server_done() {
        server_done_ = true;
        confirmed_ = true;
    }

    // The server's full board state at shot time shot_t_s (the snapshot's own t, not the
    // continuous timeline: at a pocketing, offset + t - offset may land a hair before it),
    // arrived at local_s.
    void confirm(std::span<const BodyState> server, double shot_t_s, double local_s);
    // Some body's drawn offset is still moving towards the server's.
    bool blending(double local_s) const;

    // The bodies to draw at continuous time t_s, sorted by id. `server`: the server's sample at
    // t_s when its states reach t_s, else null (the prediction, offset by the blend, is drawn).
    std::vector<RenderedBody> draw(double t_s, double local_s,
                                   const std::vector<RenderedBody>* server) const;

    // The predicted collision, cushion and pocket sounds (times on the continuous timeline).
    std::vector<SoundCue> cues() const;
    // True when a server sound of `turn` at shot time t_s matches a predicted one not yet
    // claimed (it was already played and must not play twice).
    bool claim_cue(int turn, SoundKind kind, double t_s);

    const PredictionStats& stats() const { return stats_; }

private:
    // A step of the measured difference, faded in linearly over blend_s.
    struct Fade {
        Vec2 step{};
        double start_local_s = 0.0;
    };
    struct Blend {
        Vec2 target{};           // the latest measured difference (server - predicted)
        std::vector<Fade> fades; // steps not yet fully drawn
        bool server_pocketed = false;
        bool counted = false;
    };
    Vec2 drawn_offset(const Blend& blend, double local_s) const;

    PhysicsConfig physics_;
    PredictionConfig config_;
    bool active_ = false;
    bool confirmed_ = false;
    bool server_done_ = false;
    int turn_ = -1;
    double offset_s_ = 0.0;
    Trajectory trajectory_;
    std::vector<Event> events_;
    std::vector<bool> claimed_; // per event
    std::map<int, Blend> blends_;
    PredictionStats stats_;
};

} // namespace carrom::client
