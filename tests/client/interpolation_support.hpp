#pragma once
// What the interpolation tests share: the standard board, and bodies and snapshots built in one
// line.

#include "carrom/client/interpolation_buffer.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace carrom::client::test {

inline const BoardGeometry kGeometry = make_board_geometry(PhysicsConfig{});

// Body id 0 is the queen, every other id a white coin.
inline BodyState body(int id, Vec2 pos, Vec2 vel = {}, bool pocketed = false) {
    return {id, id == 0 ? BodyKind::Queen : BodyKind::White, pos, vel, pocketed};
}

inline Snapshot snap(std::uint64_t seq, double t, bool key, std::vector<BodyState> bodies) {
    return {seq, t, key, std::move(bodies)};
}

} // namespace carrom::client::test
