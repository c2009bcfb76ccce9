#pragma once
// Short messages for the player (pockets, fouls, extra turns, errors), newest last, each shown
// for a few seconds. Invariant: no two lines shown at once have the same text (posting a line
// that is still shown moves it to the newest place with a new time).

#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace carrom::client {

enum class Tone { Info, Good, Foul, Error };

struct HudLine {
    std::string text;
    Tone tone = Tone::Info;
    double posted_s = 0.0; // local time
};

class HudLog {
public:
    explicit HudLog(std::size_t capacity = 5, double show_s = 6.0)
        : capacity_(capacity), show_s_(show_s) {}
    void post(std::string text, Tone tone, double local_s);
    // Lines still shown at local_s, oldest first.
    std::vector<HudLine> visible(double local_s) const;
    const std::deque<HudLine>& all() const { return lines_; }
    // Forgets every line (a replay that went back in time: later lines would tell the future).
    void clear() { lines_.clear(); }

private:
    std::size_t capacity_;
    double show_s_;
    std::deque<HudLine> lines_;
};

} // namespace carrom::client
