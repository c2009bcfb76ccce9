#pragma once
// The unattended modes a run's flags ask for, as the one mode the window holds: each frame goes
// to them in a fixed order (autoplay, final state, screenshot, timeout, frame benchmark) until
// one ends the run.

#include "app.hpp"
#include "unattended_mode.hpp"

#include <memory>
#include <vector>

namespace carrom::client::app {

class UnattendedModes final : public UnattendedMode {
public:
    explicit UnattendedModes(std::vector<std::unique_ptr<UnattendedMode>> modes)
        : modes_(std::move(modes)) {}
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return done_; }

private:
    std::vector<std::unique_ptr<UnattendedMode>> modes_;
    std::optional<int> done_;
};

// The match window's modes `options` ask for (--autoplay, --final-state, --screenshot,
// --timeout, --bench-frames), null for none; a timeout counts from this call.
std::unique_ptr<UnattendedMode> make_unattended_mode(const AppOptions& options);

// The --replay window's: --final-state, --screenshot, --timeout (a replay has no turn to
// autoplay and no benchmark), null for none; a timeout counts from this call.
std::unique_ptr<UnattendedMode> make_replay_unattended_mode(const AppOptions& options);

} // namespace carrom::client::app
