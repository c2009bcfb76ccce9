#pragma once
// Quick match between identified players (docs/ratings.md, "Fair pairing"): two waiting players
// meet when their ratings differ by at most the acceptable gap of the one who has waited longer.
// The gap starts at kInitialGap points and widens by kGapPerSecond points per whole second
// waited, without a bound; the server's bot fallback (--quick-match-bot, 20 s by default) ends
// the wait as for guests.

#include <cstddef>
#include <optional>
#include <span>
#include <utility>

namespace carrom::ratings {

inline constexpr double kInitialGap = 100.0;  // points, at 0 s waited
inline constexpr double kGapPerSecond = 25.0; // points per whole second waited

// kInitialGap + kGapPerSecond * floor(waited_s); waited_s < 0 counts as 0.
double acceptable_gap(double waited_s);

struct WaitingPlayer {
    double rating = 0.0;   // points
    double waited_s = 0.0; // seconds since the player asked for a quick match
};

// The pair (indices into waiting, first < second) with the smallest rating difference among
// those within the acceptable gap; ties go to the pair with the lower indices (the queue's
// order: earlier arrivals first). None when no pair is acceptable.
std::optional<std::pair<std::size_t, std::size_t>>
closest_acceptable_pair(std::span<const WaitingPlayer> waiting);

} // namespace carrom::ratings
