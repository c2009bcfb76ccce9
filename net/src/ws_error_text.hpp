#pragma once
// Plain-word sentences for what went wrong with a connection, for people (and the status
// detail of net::Connection). Private to net/src.

#include "carrom/net/ws_url.hpp"

#include <boost/system/error_code.hpp>

#include <chrono>
#include <cstdint>
#include <string>

namespace carrom::net {

// "Could not find the server host 'HOST' (no such host name)."
std::string resolve_error_text(const WsUrl& url, const boost::system::error_code& ec);
// "Could not reach HOST:PORT: connection refused."
std::string connect_error_text(const WsUrl& url, const boost::system::error_code& ec);
// "Could not reach HOST:PORT: no answer within 5 s."
std::string connect_timeout_text(const WsUrl& url, std::chrono::milliseconds timeout);
// "HOST:PORT answered, but not as a WebSocket server (...)."
std::string handshake_error_text(const WsUrl& url, const boost::system::error_code& ec);
// After the connection was open: a close frame from the server (code, reason) or a lost link.
std::string read_error_text(const WsUrl& url, const boost::system::error_code& ec,
                            std::uint16_t close_code, const std::string& close_reason);
// "Nothing arrived from HOST:PORT for 10 s: the link is silent, taken for lost."
std::string silence_text(const WsUrl& url, std::chrono::milliseconds timeout);
// What a WebSocket close code means, in a few words ("the server is shutting down").
std::string close_code_meaning(std::uint16_t close_code);

} // namespace carrom::net
