#pragma once
// The pointer gesture a player makes for a chosen shot (carrom-client --autoplay makes it with
// mouse events through the window, as a player would): press in the baseline band away from the
// striker and slide it to the shot's position, then press on the striker and pull back along the
// shot's line by the length that gives its power (the aim controller's inverse). Board px, from
// any of the four sides; the app maps the points to window px through the turned view.

#include "carrom/client/aim_controller.hpp"
#include "carrom/config.hpp"
#include "carrom/rules/seat.hpp"
#include "carrom/scene.hpp"

#include <vector>

namespace carrom::client {

struct GestureStep {
    enum class Kind { Press, Move, Release };
    Kind kind = Kind::Move;
    Vec2 board_px{};
};

// The steps for `shot` (x along the side's baseline, absolute angle) with the striker idle at
// striker_along on that baseline. Played through an AimController that began the turn there, on
// a board where the shot's placement is legal, the release gives the shot (x clamped to the
// baseline's range, power within the controller's resolution, at least just past the dead zone).
std::vector<GestureStep> shot_gesture(const PhysicsConfig& physics, const AimConfig& aim,
                                      rules::Side side, double striker_along, const Shot& shot);

} // namespace carrom::client
