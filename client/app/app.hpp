#pragma once
// The desktop client's window loop: lobby, match view, input, sound, screenshots and the frame
// benchmark.

#include "carrom/client/client_session.hpp"
#include "carrom/proto/types.hpp"

#include <optional>
#include <string>
#include <vector>

namespace carrom::client::app {

struct AppOptions {
    std::string url = "ws://127.0.0.1:7777"; // carrom-server's default port
    std::string ca_file; // wss://: a private CA trusted besides the system's (--ca-file)
    std::string name = "Player";
    // The player key sent in hello (--identity FILE, else the default file; docs/ratings.md).
    std::optional<std::string> identity;
    std::optional<RoomRequest> request; // from the flags; else the lobby asks
    bool demo = false;                  // offline: a local stand-in server (DemoLink)
    double demo_break_at_s = 1.5;
    double demo_autoplay_s = -1.0; // >= 0: the demo plays our shots too
    bool mute = false;
    // Window multisampling (antialiasing) level; 0 = off. The board and the pieces are painted
    // antialiased into textures anyway; MSAA on the window only smooths the aim line.
    unsigned msaa = 0;
    unsigned width = 900;
    unsigned height = 900;
    std::string screenshot_path; // non-empty: save a PNG after `frames` frames and exit
    int frames = 120;
    // With a screenshot: also wait until this many shot results have arrived and the board is
    // drawn at rest again.
    int after_shots = 0;
    // With a screenshot: wait for the card between two boards (--board-summary), for the
    // game-over panel (--game-over).
    bool board_summary_shot = false;
    bool game_over_shot = false;
    std::string report_path; // with a screenshot: what it shows as JSON (board_report.hpp)
    double timeout_s = 0.0;  // > 0: exit with code 3 if still running after this many seconds
    int bench_frames = 0;    // > 0: render that many demo frames and print frame times as JSON
    // Plays our turns with the bots library's strategy at this level, through the mouse input
    // path (auto_player.hpp).
    std::optional<proto::BotLevel> autoplay;
    // Non-empty: when the game is over and drawn at rest, write its final state there as JSON
    // (board_report.hpp) and exit with code 0.
    std::string final_state_path;
    // carrom-client --replay (replay_view.hpp): the playback speed (0.25 to 4) and, if >= 0, the
    // replay time to start at, paused.
    double replay_speed = 1.0;
    double replay_at_s = -1.0;
    // Non-empty: write each frame drawn in a room and each shot sent there (frame_log.hpp).
    std::string frame_log_path;
    // The settings file (settings_file.hpp); empty: $XDG_CONFIG_HOME/carrom/settings.json.
    std::string settings_path;
    // --input: keys and clicks to give the window unattended (input_script_mode.hpp).
    std::vector<std::string> input_script;
};

// Runs until the window closes; returns the process exit code.
int run_app(const AppOptions& options);

} // namespace carrom::client::app
