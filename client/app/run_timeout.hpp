#pragma once
// --timeout S: ends a run still going S seconds (wall clock) after it started, with exit code 3
// and a sentence on stderr saying what the run was doing (UnattendedFrame::progress).

#include "unattended_mode.hpp"

#include <chrono>

namespace carrom::client::app {

class RunTimeout final : public UnattendedMode {
public:
    // The run starts now.
    explicit RunTimeout(double timeout_s)
        : timeout_s_(timeout_s), started_(std::chrono::steady_clock::now()) {}
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return done_; }

private:
    double timeout_s_;
    std::chrono::steady_clock::time_point started_;
    std::optional<int> done_;
};

} // namespace carrom::client::app
