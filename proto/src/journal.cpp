// The journal model's names and small helpers (see journal.hpp).

#include "carrom/proto/journal.hpp"

#include <algorithm>
#include <type_traits>

namespace carrom::proto {

bool is_match_id(std::string_view text) {
    return !text.empty() && text.size() <= kMaxMatchIdBytes &&
           std::all_of(text.begin(), text.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                      c == '_' || c == '-';
           });
}

std::string_view to_string(ForfeitReason reason) {
    return enum_names::name_or_unknown(kForfeitReasonNames, reason);
}

bool parse(std::string_view text, ForfeitReason& out) {
    return enum_names::parse_into(kForfeitReasonNames, text, out);
}

std::string_view event_type(const JournalEvent& event) {
    return std::visit(
        [](const auto& e) -> std::string_view {
            using T = std::decay_t<decltype(e)>;
            if constexpr (std::is_same_v<T, StrokeEntry>) {
                return "stroke";
            } else if constexpr (std::is_same_v<T, ClockExpiredEntry>) {
                return "clock_expired";
            } else if constexpr (std::is_same_v<T, ForfeitEntry>) {
                return "forfeit";
            } else if constexpr (std::is_same_v<T, SeatJoinedEntry>) {
                return "join";
            } else if constexpr (std::is_same_v<T, SeatLeftEntry>) {
                return "leave";
            } else if constexpr (std::is_same_v<T, SeatDroppedEntry>) {
                return "drop";
            } else if constexpr (std::is_same_v<T, SeatReturnedEntry>) {
                return "return";
            } else {
                static_assert(std::is_same_v<T, RematchEntry>);
                return "rematch";
            }
        },
        event);
}

const OutcomeRecord* outcome_of(const JournalEvent& event) {
    if (const auto* s = std::get_if<StrokeEntry>(&event)) {
        return &s->outcome;
    }
    if (const auto* c = std::get_if<ClockExpiredEntry>(&event)) {
        return &c->outcome;
    }
    if (const auto* f = std::get_if<ForfeitEntry>(&event)) {
        return &f->outcome;
    }
    return nullptr;
}

} // namespace carrom::proto
