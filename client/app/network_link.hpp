#pragma once
// The factory for real network links (WebSocket, net::Connection from net/).

#include "carrom/client/client_session.hpp"
#include "carrom/client/connection.hpp"

#include <optional>
#include <string>

namespace carrom::client::app {

// url: ws:// or wss://HOST:PORT[/path]. Returns an empty string if it looks right, else a
// sentence.
std::string check_url(const std::string& url);
// Links to the URL the session asks for. ca_file: for wss://, certificate authorities trusted
// besides the system's ("" = none).
LinkFactory make_network_link_factory(const std::string& ca_file);
// The session's settings for the window: the defaults, with jitter on the reconnect back-off,
// the player key to say hello with (none: a guest) and the server address the player gave
// (empty in the demo).
SessionConfig network_session_config(const std::optional<std::string>& identity,
                                     const std::string& address);

} // namespace carrom::client::app
