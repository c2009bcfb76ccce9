#pragma once
// --screenshot PATH (--frames N, --after-shots K, --board-summary, --game-over, --report FILE):
// after N frames, once K shot results have arrived and the board is drawn at rest again (with
// --board-summary once the card between two boards is drawn, with --game-over once the game-over
// panel is), saves the window as a PNG and,
// with --report, what it shows as JSON (board_report.hpp); then ends the run (exit code 0, or 1
// when a file cannot be written).

#include "app.hpp"
#include "unattended_mode.hpp"

#include <string>

namespace carrom::client::app {

class ScreenshotMode final : public UnattendedMode {
public:
    explicit ScreenshotMode(const AppOptions& options)
        : path_(options.screenshot_path), report_path_(options.report_path),
          frames_(options.frames), after_shots_(options.after_shots),
          board_summary_(options.board_summary_shot), game_over_(options.game_over_shot) {}
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return done_; }

private:
    bool due(const UnattendedFrame& frame) const;
    int save(const UnattendedFrame& frame) const;

    std::string path_;
    std::string report_path_; // empty: no report
    int frames_;
    int after_shots_;
    bool board_summary_; // wait for the card between two boards
    bool game_over_;     // wait for the game-over panel (the game over and at rest)
    std::optional<int> done_;
};

} // namespace carrom::client::app
