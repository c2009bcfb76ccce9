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
// ca_file: for wss://, certificate authorities trusted besides the system's ("" = none).
LinkFactory make_network_link_factory(const std::string& url, const std::string& ca_file);
// The session's settings for the window: the defaults, with jitter on the reconnect back-off,
// and the player key to say hello with (none: a guest).
SessionConfig network_session_config(const std::optional<std::string>& identity);

} // namespace carrom::client::app
