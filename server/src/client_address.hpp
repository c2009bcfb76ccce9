#pragma once
// Private to server/src: the address a connection counts under for the per-address limits
// (--max-connections-per-address, --http-rate). Behind a proxy every connection comes from the
// proxy's address; a proxy named by --trusted-proxy appends the client's address to the request's
// X-Forwarded-For (HAProxy: `option forwardfor`), and that address counts instead.

#include <string>
#include <string_view>
#include <vector>

namespace carrom::server {

// `trusted`: addresses or networks ("10.0.0.0/8", "fd00::/8", "127.0.0.1"), as --trusted-proxy
// gives them. The error for the first entry that is neither, or "".
std::string trusted_proxies_problem(const std::vector<std::string>& trusted);

// `peer` (the connection's address) unless it is one of `trusted` and `forwarded_for` ends with
// an IP address: then that last address (the one the trusted proxy appended; the ones before it
// came from the client and count for nothing). A header that does not end with one is ignored.
std::string client_address(const std::string& peer, std::string_view forwarded_for,
                           const std::vector<std::string>& trusted);

} // namespace carrom::server
