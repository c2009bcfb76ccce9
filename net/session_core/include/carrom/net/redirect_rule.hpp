#pragma once
// Whether a client follows a server's `redirect` to `to_url` (docs/protocol.md, "Redirects"):
// only to an address of the cluster the player chose. No I/O; net::SessionCore and its web port
// (web/js/session_core.js, redirectAllowed) apply the same rule.

#include <string>
#include <string_view>

namespace carrom::net {

// The host of a ws:// or wss:// URL, lowercased ("[::1]" keeps its brackets); empty when url is
// not ws:// or wss://, has user information ('@'), a space or a control character, or no host.
std::string ws_url_host(std::string_view url);

// True when `to_url` is ws:// or wss://, is wss:// if `from_url` (the connection that got the
// redirect) is, and has the host of `address` (the address the player gave; its port and path
// may differ).
bool redirect_allowed(std::string_view from_url, std::string_view address, std::string_view to_url);

} // namespace carrom::net
