#pragma once
// What the window says over the board while the connection is lost: "Reconnecting..." with the
// try under way or the time to the next, why the link was lost and how long the seat is held;
// then "Connection lost: <reason>" once the session gives up.

#include "carrom/client/client_session.hpp"

#include <string>
#include <vector>

namespace carrom::client {

struct ReconnectText {
    std::string title;              // "Reconnecting..." or "Disconnected"
    std::vector<std::string> lines; // one sentence each
    friend bool operator==(const ReconnectText&, const ReconnectText&) = default;
};

// For a session in a room whose link was lost (phase Reconnecting, Connecting or Greeting while
// resuming) or that gave up (Failed).
ReconnectText reconnect_text(SessionPhase phase, const ReconnectInfo& info,
                             const std::string& status);

} // namespace carrom::client
