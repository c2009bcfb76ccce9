#pragma once
// What happens during a simulation, as data.

#include "carrom/enum_names.hpp"
#include "carrom/vec2.hpp"

#include <cstdint>
#include <string_view>

namespace carrom {

enum class EventKind : std::uint8_t {
    Collision, // two bodies (a, b) exchanged an impulse
    Cushion,   // body a hit cushion b (0 left, 1 right, 2 top, 3 bottom)
    Pocket,    // body a entered pocket b (0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right)
    Stop,      // body a fell to the stop speed and came to rest
};
inline constexpr enum_names::Table<EventKind, 4> kEventKindNames{
    {{EventKind::Collision, "collision"},
     {EventKind::Cushion, "cushion"},
     {EventKind::Pocket, "pocket"},
     {EventKind::Stop, "stop"}}};

enum Cushion : int { kCushionLeft = 0, kCushionRight = 1, kCushionTop = 2, kCushionBottom = 3 };

struct Event {
    double t_s = 0.0; // time since the start of the simulation
    EventKind kind = EventKind::Collision;
    int a = -1;           // body id
    int b = -1;           // body id (Collision), cushion index (Cushion), pocket index (Pocket)
    double impulse = 0.0; // magnitude of the normal impulse, mass * px/s (Collision, Cushion)
    Vec2 pos_px{};        // centre of body a at the event
};

std::string_view to_string(EventKind kind);

} // namespace carrom
