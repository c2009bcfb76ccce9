#pragma once
// Turning pointer and key input into a shot, in board px (the app maps window px to board px
// first, so the same logic works for a flipped view).
//
// On the player's turn the striker sits on their baseline, on any of the four sides (positions
// along it are x for the bottom and top baselines, y for the left and right ones, as on the wire):
//  - press anywhere in the baseline band (not on the striker) and drag: the striker follows the
//    pointer along the baseline, clamped to the legal range; arrow keys move it in fine steps;
//  - press on the striker and pull back: the shot goes from the pointer towards the striker, its
//    power grows with the pull length up to max power; release shoots, Escape cancels, and a
//    pull shorter than the dead zone is no shot.
// The placement is checked as it changes: overlapping a piece on the board is illegal and is
// shown before release; an illegal placement never produces a shot.

#include "carrom/client/snapshot.hpp"
#include "carrom/config.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"

#include <optional>
#include <span>
#include <string>

namespace carrom::client {

struct AimConfig {
    double full_power_drag_px = 160.0; // pull length (board px) that gives max power
    double dead_zone_px = 12.0;        // shorter pulls shoot nothing
    double grab_factor = 1.5;          // the striker is grabbed within this many radii
    double slide_band_px = 45.0;       // presses this close to the baseline slide the striker
    double fine_step_px = 1.0;         // one arrow key press
    double coarse_step_px = 10.0;      // with Shift
};

enum class AimPhase { Inactive, Idle, Sliding, Pulling };

struct ShotIntent {
    double x_px = 0.0; // along the baseline
    double angle_rad = 0.0;
    double power = 0.0;
};

struct Placement {
    bool legal = true;
    int blocking_id = -1; // the piece the striker overlaps, if any
};

// The striker centre x clamped to the baseline's legal range.
double clamp_baseline_x(const PhysicsConfig& config, double x_px);
// The striker centre on a side's baseline at a position along it (rules::striker_for's place).
Vec2 baseline_point(const PhysicsConfig& config, rules::Side side, double along_px);
// A board point's position along a side's baseline (x for bottom and top, y for left and right)
// and its distance across it (from the line the striker centre sits on).
double along_baseline(rules::Side side, Vec2 p);
double across_baseline(const PhysicsConfig& config, rules::Side side, Vec2 p);
// Power for a pull of drag_px board px: 0 inside the dead zone, linear above it, capped at max.
double power_from_drag(const PhysicsConfig& config, const AimConfig& aim, double drag_px);
// Whether a striker at pos overlaps an unpocketed piece (the striker itself is ignored).
Placement check_placement(const PhysicsConfig& config, Vec2 striker_px,
                          std::span<const BodyState> bodies);

class AimController {
public:
    AimController(const PhysicsConfig& config, const AimConfig& aim = {});

    // Our turn starts: the striker goes to x along our side's baseline (clamped).
    void begin_turn(rules::Side side, double x_px);
    // Not our turn (or a spectator): no input is taken.
    void end_turn();

    // Pointer in board px. Pieces are the current board, for the placement check.
    void pointer_down(Vec2 p, std::span<const BodyState> pieces);
    void pointer_move(Vec2 p, std::span<const BodyState> pieces);
    std::optional<ShotIntent> pointer_up(Vec2 p, std::span<const BodyState> pieces);
    // Arrow keys: move the striker by steps along the baseline (+1 or -1 times a step, in the
    // direction of growing x, or y for a side baseline).
    void nudge(int direction, bool coarse, std::span<const BodyState> pieces);
    // Escape: drop the pull or the slide, keeping the striker where it is.
    void cancel();

    AimPhase phase() const { return phase_; }
    rules::Side side() const { return side_; }
    Vec2 striker_px() const;
    double striker_x() const { return x_px_; } // along the baseline
    const Placement& placement() const { return placement_; }
    // The shot a release would make now (meaningful while pulling).
    ShotIntent pending_shot() const;
    // Pull as a fraction of full power, 0..1.
    double power_fraction() const;
    // True once after the striker x changed (to tell the server the aim moved).
    bool take_moved();

private:
    void set_x(double x_px, std::span<const BodyState> pieces);

    PhysicsConfig config_;
    AimConfig aim_;
    AimPhase phase_ = AimPhase::Inactive;
    rules::Side side_ = rules::Side::Bottom;
    double x_px_ = 300.0;
    Vec2 pointer_px_{};
    Placement placement_;
    bool moved_ = false;
};

} // namespace carrom::client
