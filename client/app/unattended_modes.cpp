#include "unattended_modes.hpp"

#include "auto_player.hpp"
#include "final_state_mode.hpp"
#include "frame_bench.hpp"
#include "input_script_mode.hpp"
#include "run_timeout.hpp"
#include "screenshot_mode.hpp"

namespace carrom::client::app {

void UnattendedModes::on_frame(UnattendedFrame& frame) {
    for (const auto& mode : modes_) {
        if (done_) {
            return;
        }
        mode->on_frame(frame);
        done_ = mode->done();
    }
}

namespace {

// Which modes a window holds; the rest of `options` configures them.
struct ModeSet {
    bool autoplay = false;
    bool bench = false;
};

std::unique_ptr<UnattendedMode> make_modes(const AppOptions& options, ModeSet set) {
    std::vector<std::unique_ptr<UnattendedMode>> modes;
    if (set.autoplay && !options.input_script.empty()) {
        modes.push_back(
            std::make_unique<InputScriptMode>(options.input_script, !options.request.has_value()));
    }
    if (set.autoplay && options.autoplay) {
        modes.push_back(std::make_unique<AutoPlayer>(*options.autoplay, 1));
    }
    if (!options.final_state_path.empty()) {
        modes.push_back(std::make_unique<FinalStateMode>(options.final_state_path));
    }
    if (!options.screenshot_path.empty()) {
        modes.push_back(std::make_unique<ScreenshotMode>(options));
    }
    if (options.timeout_s > 0.0) {
        modes.push_back(std::make_unique<RunTimeout>(options.timeout_s));
    }
    if (set.bench && options.bench_frames > 0) {
        modes.push_back(std::make_unique<FrameBench>(options.bench_frames, options.msaa));
    }
    if (modes.empty()) {
        return nullptr;
    }
    if (modes.size() == 1) {
        return std::move(modes.front());
    }
    return std::make_unique<UnattendedModes>(std::move(modes));
}

} // namespace

std::unique_ptr<UnattendedMode> make_unattended_mode(const AppOptions& options) {
    return make_modes(options, ModeSet{.autoplay = true, .bench = true});
}

std::unique_ptr<UnattendedMode> make_replay_unattended_mode(const AppOptions& options) {
    return make_modes(options, ModeSet{.autoplay = false, .bench = false});
}

} // namespace carrom::client::app
