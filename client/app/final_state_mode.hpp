#pragma once
// --final-state PATH: once the game is over and drawn at rest (a replay: at its end;
// UnattendedFrame::at_end), writes its final state as JSON (board_report.hpp) and ends the run
// (exit code 0, or 1 when the file cannot be written).

#include "unattended_mode.hpp"

#include <string>

namespace carrom::client::app {

class FinalStateMode final : public UnattendedMode {
public:
    explicit FinalStateMode(std::string path) : path_(std::move(path)) {}
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return done_; }

private:
    std::string path_;
    std::optional<int> done_;
};

} // namespace carrom::client::app
