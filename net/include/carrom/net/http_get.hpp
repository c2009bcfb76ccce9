#pragma once
// One HTTP/1.1 GET (carrom-client --replay URL fetching a match journal: http:// only; its
// players and leaderboard views: http:// or https://), no redirects, a body size limit and one
// deadline for the whole exchange. Blocking; Boost stays in net/src/http_get.cpp.

#include "carrom/net/ws_url.hpp"

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

namespace carrom::net {

struct HttpLimits {
    std::size_t max_body_bytes = 16U << 20U;  // a longer body is an error, not cut short
    std::chrono::milliseconds timeout{10000}; // connect, send and receive together
};

struct HttpResponse {
    unsigned status = 0; // http_get: 200 only (other statuses are errors); http_get_any_status: any
    std::string body;
};

// http://HOST[:PORT][/PATH] (port 80 by default) as host, port and target, or one sentence.
std::variant<WsUrl, std::string> parse_http_url(std::string_view url);

// The body of a 200 answer, or one sentence saying what went wrong: a bad address, a host not
// found, a refused connection, no answer within the timeout, another status than 200 ("... answered
// 404 Not Found."), a body over the limit.
std::variant<HttpResponse, std::string> http_get(std::string_view url, const HttpLimits& limits);

// For a carrom-server's JSON API (carrom-client's ratings, leaderboard and match list):
// http:// or https:// (port 443 by default; TLS as for wss://: the certificate verified for the
// host against the system's CAs and ca_file, "" for none), and an answer of any status comes
// back with its body (an error's JSON too). The same sentences as http_get otherwise.
std::variant<HttpResponse, std::string>
http_get_any_status(std::string_view url, const HttpLimits& limits, const std::string& ca_file);

} // namespace carrom::net
