#pragma once
// One plain HTTP/1.1 GET (carrom-client --replay URL fetching a match journal): http:// only,
// no redirects, a body size limit and one deadline for the whole exchange. Blocking; Boost stays
// in net/src/http_get.cpp.

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
    unsigned status = 0; // 200 only: other statuses are errors
    std::string body;
};

// http://HOST[:PORT][/PATH] (port 80 by default) as host, port and target, or one sentence.
std::variant<WsUrl, std::string> parse_http_url(std::string_view url);

// The body of a 200 answer, or one sentence saying what went wrong: a bad address, a host not
// found, a refused connection, no answer within the timeout, another status than 200 ("... answered
// 404 Not Found."), a body over the limit.
std::variant<HttpResponse, std::string> http_get(std::string_view url, const HttpLimits& limits);

} // namespace carrom::net
