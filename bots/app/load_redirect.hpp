#pragma once
// carrom-load's decision on a cluster's `redirect` (docs/protocol.md, "Redirects"), as
// net::SessionCore decides for the other clients: follow only to the host of the server's
// address, in the load's own scheme (ws, or wss with --tls), at most kMaxRedirects in a row.
// No I/O.

#include "carrom/proto/server_messages.hpp"

#include <boost/asio/ip/tcp.hpp>

#include <cstdint>
#include <string>
#include <variant>

namespace carrom::load {

// Where a redirected player goes: the URL's port and path on the server's address, hello with
// the seat's token when it held one, else join `code`.
struct RedirectPlan {
    std::uint16_t port = 0;
    std::string target = "/"; // path and query
    std::string code;         // the room to join when no seat comes back; empty: none
    proto::Role as = proto::Role::Player;
    std::string token; // the seat's resume token; empty: none
    int redirects = 0; // followed in a row, this one included
};

// The link that got `redirect`: the server's address, the port and path it went to, its scheme.
struct LoadLink {
    boost::asio::ip::tcp::endpoint server;
    std::uint16_t port = 0;
    std::string target = "/";
    bool tls = false;
    int redirects = 0; // followed in a row before this one
};

// ws://ADDRESS:PORT (wss:// with TLS), IPv6 in brackets.
std::string load_url(const boost::asio::ip::tcp::endpoint& server, std::uint16_t port, bool tls);

// The plan (with `token`: the seat's, empty without one) or the sentence of the refusal
// ("redirect refused: ...").
std::variant<RedirectPlan, std::string>
plan_redirect(const LoadLink& link, const proto::Redirect& redirect, const std::string& token);

} // namespace carrom::load
