#pragma once
// The desktop client's window loop: lobby, match view, input, sound, screenshots and the frame
// benchmark.

#include "carrom/client/client_session.hpp"

#include <optional>
#include <string>

namespace carrom::client::app {

struct AppOptions {
    std::string url = "ws://127.0.0.1:8080";
    std::string name = "Player";
    std::optional<RoomRequest> request; // from the flags; else the lobby asks
    bool demo = false;                  // offline: a local stand-in server (DemoLink)
    double demo_break_at_s = 1.5;
    double demo_autoplay_s = -1.0;      // >= 0: the demo plays our shots too
    bool mute = false;
    unsigned width = 900;
    unsigned height = 900;
    std::string screenshot_path; // non-empty: save a PNG after `frames` frames and exit
    int frames = 120;
    int bench_frames = 0; // > 0: render that many demo frames and print frame times as JSON
};

// Runs until the window closes; returns the process exit code.
int run_app(const AppOptions& options);

} // namespace carrom::client::app
