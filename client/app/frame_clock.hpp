#pragma once
// The window loop's clock: real time, or a fixed 1/60 s per frame for demo screenshots and the
// frame benchmark (reproducible pictures). Seconds since the loop started.

#include <chrono>

namespace carrom::client::app {

class FrameClock {
public:
    explicit FrameClock(bool fixed_step) : fixed_(fixed_step) {}
    double now() const {
        if (fixed_) {
            return static_cast<double>(frame_) / 60.0;
        }
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    void tick() { ++frame_; } // one frame drawn

private:
    bool fixed_;
    long frame_ = 0;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

} // namespace carrom::client::app
