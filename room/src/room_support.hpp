#pragma once
// Private to room/src: small helpers the Room's source files share.

#include "carrom/proto/error.hpp"
#include "carrom/proto/server_messages.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace carrom::room {

inline proto::Error make_error(std::string_view code, std::string message) {
    return {std::string(code), std::move(message)};
}

// The event a member gets while the room's stroke waits for its journal entry past
// RoomConfig::store_pause_after_ms.
inline proto::Event store_paused_event() {
    return proto::PausedEvent{"store",
                              "The server cannot save the last stroke because its database does "
                              "not answer; the match goes on when it is back."};
}

inline std::int64_t seconds_to_ms(double s) {
    return static_cast<std::int64_t>(std::llround(s * 1000.0));
}

} // namespace carrom::room
