#include "carrom/body.hpp"
#include "carrom/event.hpp"

namespace carrom {

std::string_view to_string(BodyKind kind) {
    switch (kind) {
    case BodyKind::Black:
        return "black";
    case BodyKind::White:
        return "white";
    case BodyKind::Queen:
        return "queen";
    case BodyKind::Striker:
        return "striker";
    }
    return "unknown";
}

bool parse_body_kind(std::string_view text, BodyKind& out) {
    for (BodyKind kind : {BodyKind::Black, BodyKind::White, BodyKind::Queen, BodyKind::Striker}) {
        if (text == to_string(kind)) {
            out = kind;
            return true;
        }
    }
    return false;
}

std::string_view to_string(EventKind kind) {
    switch (kind) {
    case EventKind::Collision:
        return "collision";
    case EventKind::Cushion:
        return "cushion";
    case EventKind::Pocket:
        return "pocket";
    case EventKind::Stop:
        return "stop";
    }
    return "unknown";
}

} // namespace carrom
