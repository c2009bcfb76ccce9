#pragma once
// Parsing of the server address a player types: ws://HOST:PORT[/path] or wss://HOST:PORT[/path]
// (TLS). No Boost, no I/O.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace carrom::net {

struct WsUrl {
    std::string host;         // a name, an IPv4 address or an IPv6 address without brackets
    std::uint16_t port = 0;   // 1..65535
    std::string target = "/"; // path and query, always starting with '/'
    bool tls = false;         // wss://: TLS, the server's certificate verified for host
    // "HOST:PORT" as people write it ("[::1]:7777" for IPv6), for messages.
    std::string authority() const;
};

// The parsed url, or one sentence saying what is wrong with it. Accepts only the ws and wss
// schemes,
// a non-empty host of at most 253 bytes without spaces or control characters, and an explicit
// decimal port 1..65535.
std::variant<WsUrl, std::string> parse_ws_url(std::string_view url);

} // namespace carrom::net
