#pragma once
// --bench-frames N: the times of N frames drawn after a warm-up of 10, and their statistics as
// one JSON line on stdout (docs/client-frames.md "Frame time"); then the run ends (exit code 0).

#include "unattended_mode.hpp"

#include <string>
#include <vector>

namespace carrom::client::app {

struct FrameBenchWindow {
    unsigned width = 0; // px
    unsigned height = 0;
    unsigned msaa = 0;
    long board_paints = 0; // board band and piece atlas paints
    long hud_paints = 0;   // HUD bar paints
};

class FrameBench final : public UnattendedMode {
public:
    FrameBench(int frames, unsigned msaa) : frames_(frames), msaa_(msaa) {}
    // Records the frame shown before this one; prints the statistics after the last one.
    void on_frame(UnattendedFrame& frame) override;
    std::optional<int> done() const override { return done_; }

private:
    // Records frame number `frame` (1-based): wall and process CPU time in ms, whether pieces
    // moved. True once the last frame is recorded (false always when frames <= 0).
    bool record(int frame, double ms, double cpu_ms, bool moving);
    // {"width", "height", "msaa", "frames", "p50_ms", "p99_ms", "max_ms", "moving_frames",
    // "moving_p50_ms", "moving_p99_ms", "cpu_p50_ms", "cpu_p99_ms", "board_paints",
    // "hud_paints"}.
    std::string json(const FrameBenchWindow& window) const;

    static constexpr int kWarmupFrames = 10;
    int frames_;
    unsigned msaa_;
    std::optional<int> done_;
    std::vector<double> all_ms_;
    std::vector<double> moving_ms_;
    std::vector<double> cpu_ms_; // CPU time of the whole process (renderer threads included)
};

} // namespace carrom::client::app
