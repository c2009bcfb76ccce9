#include "frame_bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace carrom::client::app {
namespace {

// The nearest-rank percentile (p in (0, 1]); 0 for no values.
double percentile(std::vector<double> v, double p) {
    if (v.empty()) {
        return 0.0;
    }
    std::sort(v.begin(), v.end());
    const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
    return v[std::min(i, v.size() - 1)];
}

} // namespace

void FrameBench::on_frame(UnattendedFrame& frame) {
    if (!frame.shown ||
        !record(frame.number - 1, frame.shown->wall_ms, frame.shown->cpu_ms, frame.shown->moving)) {
        return;
    }
    const sf::Vector2u size = frame.window.getSize();
    std::cout << json({size.x, size.y, msaa_, frame.board_paints, frame.hud_paints}) << std::endl;
    done_ = 0;
}

bool FrameBench::record(int frame, double ms, double cpu_ms, bool moving) {
    if (frames_ <= 0 || frame <= kWarmupFrames) {
        return false;
    }
    all_ms_.push_back(ms);
    cpu_ms_.push_back(cpu_ms);
    if (moving) {
        moving_ms_.push_back(ms);
    }
    return frame >= frames_ + kWarmupFrames;
}

std::string FrameBench::json(const FrameBenchWindow& w) const {
    char line[512];
    std::snprintf(line, sizeof line,
                  "{\"width\": %u, \"height\": %u, \"msaa\": %u, \"frames\": %zu, "
                  "\"p50_ms\": %.3f, \"p99_ms\": %.3f, \"max_ms\": %.3f, \"moving_frames\": %zu, "
                  "\"moving_p50_ms\": %.3f, \"moving_p99_ms\": %.3f, \"cpu_p50_ms\": %.3f, "
                  "\"cpu_p99_ms\": %.3f, \"board_paints\": %ld, \"hud_paints\": %ld}",
                  w.width, w.height, w.msaa, all_ms_.size(), percentile(all_ms_, 0.5),
                  percentile(all_ms_, 0.99), percentile(all_ms_, 1.0), moving_ms_.size(),
                  percentile(moving_ms_, 0.5), percentile(moving_ms_, 0.99),
                  percentile(cpu_ms_, 0.5), percentile(cpu_ms_, 0.99), w.board_paints,
                  w.hud_paints);
    return line;
}

} // namespace carrom::client::app
