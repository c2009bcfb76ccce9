#pragma once
// What a window does unattended, as its flags ask (app.hpp): screenshots and their report, the
// final state, the frame benchmark, autoplay, the timeout. The match window and the --replay
// window each hold at most one mode (unattended_modes.hpp combines several) and hand it every
// frame after drawing it and before showing it; the mode may queue input for the next frame and
// end the run.

#include "carrom/client/aim_controller.hpp"
#include "carrom/client/interpolation_buffer.hpp"
#include "carrom/client/match_model.hpp"
#include "carrom/client/screen_mapping.hpp"
#include "carrom/config.hpp"
#include "carrom/proto/server_messages.hpp"

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Window/Event.hpp>

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

// The times of one whole frame, from its events to its display().
struct FrameTime {
    double wall_ms = 0.0;
    double cpu_ms = 0.0; // process CPU time (renderer threads included)
    bool moving = false; // pieces moved (MatchModel::animating)
};

// What the match window adds to a frame: the turn we may play (what --autoplay plays from).
struct LiveTurn {
    const std::optional<proto::RoomState>& room; // the newest room state
    const AimController& aim;
    bool shot_sent = false; // we shot in the current turn already
};

// One frame as a mode sees it: drawn into the window, not yet displayed.
struct UnattendedFrame {
    int number = 0; // frames drawn so far, this one included
    sf::RenderWindow& window;
    const MatchModel& model; // the HUD's model (a replay feeds it what a spectator got)
    const LiveTurn* live;    // null in a replay (no turn to play)
    // The game shown is over and drawn at rest: a match's game over with its result and nothing
    // moving, a replay's end.
    bool at_end = false;
    // What the run is doing, in words, for the timeout's sentence ("connected, 3 shots seen",
    // "replay at 12.5 of 80 s").
    std::function<std::string()> progress;
    int shots_seen = 0; // shot results the model was given
    const ScreenMapping& mapping;
    const PhysicsConfig& physics;
    const std::vector<RenderedBody>& bodies; // the pieces drawn
    std::optional<Vec2> aim_striker;         // a striker being placed, as drawn (board px)
    std::optional<Rect> overlay;             // window px covered by messages over the board
    std::optional<FrameTime> shown;          // the frame before this one, displayed
    long board_paints = 0;                   // board band and piece atlas paints so far
    long hud_paints = 0;                     // HUD bar paints so far
    std::vector<sf::Event>& input;           // events for the window to handle next frame
    bool board_summary = false;              // the card between two boards is drawn
    std::string ui = "null";    // the menus and the side area as JSON (AppWindow::ui_json)
    bool input_pending = false; // --input has tokens left (a screenshot waits for them)
};

class UnattendedMode {
public:
    virtual ~UnattendedMode() = default;
    virtual void on_frame(UnattendedFrame& frame) = 0;
    // The process exit code once the mode has ended the run.
    virtual std::optional<int> done() const = 0;
};

} // namespace carrom::client::app
