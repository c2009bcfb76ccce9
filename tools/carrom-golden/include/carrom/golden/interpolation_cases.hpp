#pragma once
// Golden cases of the board between snapshots: the interpolation buffer
// (client/src/interpolation_buffer.cpp, web/js/interpolation_buffer.js) and the playout clock
// (client/src/playout_clock.cpp, web/js/playout_clock.js). Inputs are operations in order; the
// expected output has one entry per operation.

#include "carrom/golden/golden_json.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace carrom::golden {

// Input {"motion": {"damping_per_s", "every_change_sent"}, "ops": [{"push": {"seq", "time",
// "keyframe", "bodies": [[id, kind, x, y, vx, vy, pocketed]]}} or {"sample": t}]}.
// Output per op: push -> whether it was taken; sample -> [[id, x, y, scale, alpha, falling]].
nlohmann::json replay_interpolation(const nlohmann::json& input);
// Input {"interval_factor", "ops": [{"snapshot": [server_s, local_s]} or {"render": local_s}]}.
// Output per op: snapshot -> null; render -> the render time.
nlohmann::json replay_playout(const nlohmann::json& input);

// The inputs made from a recorded stream: the first `turns` turns with motion after the first
// room state, each turn's times placed one second after the previous turn's last snapshot.
nlohmann::json interpolation_input(const std::vector<StreamLine>& stream, int turns,
                                   bool every_change_sent);
nlohmann::json playout_input(const std::vector<StreamLine>& stream, int turns);

} // namespace carrom::golden
