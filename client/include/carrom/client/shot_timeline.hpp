#pragma once
// Where each shot starts on the client's one continuous timeline (seconds of the local clock less
// the base network transit). A shot's snapshot and event times are seconds since its own t = 0
// (proto), so continuous time = the shot's start + t. The newest kTurnsKept turns are kept.

#include <cstddef>
#include <map>
#include <optional>

namespace carrom::client {

// The shot a continuous time falls in: the turn whose shot started last at or before it (turn -1
// when none is known) and the time since that shot's t = 0 (its snapshot time), seconds.
struct ShotTime {
    int turn = -1;
    double t_s = 0.0;
};

class ShotTimeline {
public:
    static constexpr std::size_t kTurnsKept = 8;

    // The continuous time of turn's t = 0, if it is known.
    std::optional<double> start_of(int turn) const;
    // Turn's t = 0 lies at continuous time start_s (replacing what was known); beyond kTurnsKept
    // turns the lowest turn numbers are forgotten.
    void place(int turn, double start_s);
    void forget(int turn) { starts_.erase(turn); }
    void clear() { starts_.clear(); }
    ShotTime shot_time(double continuous_s) const;

private:
    std::map<int, double> starts_; // turn -> continuous time of its t = 0
};

} // namespace carrom::client
