#pragma once
// What the aiming tests share.

#include "carrom/client/snapshot.hpp"

#include <numbers>
#include <vector>

namespace carrom::client::test {

inline constexpr double kPi = std::numbers::pi;
// A board with no bodies on it: nothing blocks the striker.
inline const std::vector<BodyState> kEmpty;

} // namespace carrom::client::test
