#pragma once
// carrom-client --replay: a window that plays a ReplayModel with the live match's board painter
// and HUD (fed the room states and outcome messages a spectator would have received), a status
// line ("Replay  ·  Stroke 5 / 37  ·  2x  ·  Paused") and a help line. Keys: Space play/pause,
// Right/Left next/previous stroke, Up/Down or +/- speed, Home restart. Unattended, it holds the
// match window's modes a replay has (make_replay_unattended_mode: --final-state at the replay's
// end, --screenshot, --timeout). See docs/client.md, "Replays".

#include "app.hpp"
#include "carrom/client/replay_model.hpp"

namespace carrom::client::app {

// Runs until the window closes or an unattended mode ends the run; the exit code.
int run_replay(const AppOptions& options, ReplayModel model);

} // namespace carrom::client::app
