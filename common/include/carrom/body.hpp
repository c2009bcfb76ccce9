#pragma once
// A body on the board: a coin (black, white, queen) or the striker. Plain data.

#include "carrom/vec2.hpp"

#include <cstdint>
#include <string_view>

namespace carrom {

enum class BodyKind : std::uint8_t { Black, White, Queen, Striker };

// The engine's body: what the simulation moves and the rules read, full double precision in
// board px and px/s. proto::BoardBody (a body of room_state, the wire's form, compared field by
// field) and client::BodyState (a body as a snapshot gave it to the client: 0.01 px as the
// server quantised it, a pocketed body at its last drawn place) carry the same fields for their
// own layer, so a change of the wire or of the client never reaches the engine's type.
struct Body {
    int id = 0; // caller's id, unique within a scene; events name bodies by it
    BodyKind kind = BodyKind::Black;
    Vec2 pos_px{};         // centre
    Vec2 vel_px_s{};       // zero for a body at rest
    bool pocketed = false; // a pocketed body takes no part in the simulation
};

std::string_view to_string(BodyKind kind);
// Parses "black", "white", "queen", "striker"; returns false for anything else.
bool parse_body_kind(std::string_view text, BodyKind& out);

} // namespace carrom
