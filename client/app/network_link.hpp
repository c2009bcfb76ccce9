#pragma once
// The factory for real network links (WebSocket, net::Connection from net/).

#include "carrom/client/connection.hpp"

#include <string>

namespace carrom::client::app {

// url: ws://HOST:PORT[/path]. Returns an empty string if it looks right, else a sentence.
std::string check_url(const std::string& url);
LinkFactory make_network_link_factory(const std::string& url);

} // namespace carrom::client::app
