#include "carrom/body.hpp"
#include "carrom/event.hpp"

namespace carrom {

std::string_view to_string(BodyKind kind) {
    return enum_names::name_or_unknown(kBodyKindNames, kind);
}

bool parse_body_kind(std::string_view text, BodyKind& out) {
    return enum_names::parse_into(kBodyKindNames, text, out);
}

std::string_view to_string(EventKind kind) {
    return enum_names::name_or_unknown(kEventKindNames, kind);
}

} // namespace carrom
