#pragma once
// The client's view of a board snapshot, independent of the wire format (the message handler
// converts proto snapshots into these). Board px, px/s, server match time in s.

#include "carrom/body.hpp"
#include "carrom/vec2.hpp"

#include <cstdint>
#include <vector>

namespace carrom::client {

// A body as the client knows it at a snapshot's time: the fields of carrom::Body, taken from
// room_state (proto::BoardBody) or a snapshot (values the server quantised to 0.01 px and
// px/s; a body a delta names as pocketed keeps the position the client last had for it, at
// rest). The client's interpolation, aiming and prediction work on it, never on the wire's type.
struct BodyState {
    int id = 0;
    BodyKind kind = BodyKind::Black;
    Vec2 pos_px{};
    Vec2 vel_px_s{};
    bool pocketed = false;
};

// A keyframe lists every body; a delta lists only the bodies that changed since the previous
// snapshot (the others keep their position and are at rest).
struct Snapshot {
    std::uint64_t seq = 0;
    double time_s = 0.0; // server match time the bodies were sampled at
    bool keyframe = false;
    std::vector<BodyState> bodies;
};

} // namespace carrom::client
