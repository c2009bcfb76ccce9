#include "carrom/client/hud_log.hpp"

#include <algorithm>

namespace carrom::client {

void HudLog::post(std::string text, Tone tone, double local_s) {
    // A line still shown is not shown twice: the old copy goes, the new one is the newest.
    std::erase_if(lines_, [&](const HudLine& line) {
        return line.text == text && local_s - line.posted_s <= show_s_;
    });
    lines_.push_back({std::move(text), tone, local_s});
    while (lines_.size() > capacity_) {
        lines_.pop_front();
    }
}

std::vector<HudLine> HudLog::visible(double local_s) const {
    std::vector<HudLine> out;
    for (const HudLine& line : lines_) {
        if (local_s - line.posted_s <= show_s_) {
            out.push_back(line);
        }
    }
    return out;
}

} // namespace carrom::client
