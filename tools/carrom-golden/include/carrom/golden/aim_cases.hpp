#pragma once
// Golden cases of aiming (client/src/aim_controller.cpp, aim_gesture.cpp, screen_mapping.cpp;
// web/js/aim_controller.js, screen_mapping.js): pointer gestures in window px on a view turned
// for one seat's side, mapped to board px and played through the aim controller, and what the
// controller says after each event (phase, striker position, placement, the shot on release).

#include <nlohmann/json.hpp>

#include <string>

namespace carrom::golden {

// Input {"view": {"origin_x", "origin_y", "scale", "board_size", "turns"}, "side",
// "gestures": [{"name", "start_x", "pieces": [[id, kind, x, y, pocketed]], "events": [{"down":
// [x, y]} | {"move": [x, y]} | {"up": [x, y]} | {"nudge": [direction, coarse]} | {"cancel":
// true}]}]}. Output per gesture, per event: {"phase", "x", "legal", "blocking", "moved"} and on
// "up" "shot": [x, angle, power] or null.
nlohmann::json replay_aim(const nlohmann::json& input);

// The gestures for the seat shooting from `side` ("bottom", "right", "top", "left").
nlohmann::json aim_input(const std::string& side);

} // namespace carrom::golden
