#pragma once
// Private to room/src: small helpers the Room's source files share.

#include "carrom/proto/error.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

namespace carrom::room {

inline proto::Error make_error(std::string_view code, std::string message) {
    return {std::string(code), std::move(message)};
}

inline std::int64_t seconds_to_ms(double s) {
    return static_cast<std::int64_t>(std::llround(s * 1000.0));
}

} // namespace carrom::room
