#pragma once
// GETs on the carrom-server the client plays on (its players, leaderboard and match journals,
// docs/protocol.md), in the background: the frame loop starts a request and picks its answer up
// in a later frame, never waiting for the network. HTTP on the WebSocket URL's host and port
// (https:// for wss://, with the same --ca-file). Each request runs on a thread of its own with a
// 5 s deadline; at most kMaxInFlight run at once.

#include "carrom/client/player_record.hpp"

#include <cstddef>
#include <future>
#include <string>
#include <vector>

namespace carrom::client::app {

class ApiFetcher {
public:
    static constexpr std::size_t kMaxInFlight = 8;

    struct Done {
        std::string key; // the requester's tag
        ApiAnswer answer;
    };

    // ws_url: the server's WebSocket address; "" (the demo): no server, every get() refused.
    ApiFetcher(const std::string& ws_url, std::string ca_file);
    // Waits for the requests still running (each ends within its deadline).
    ~ApiFetcher() = default;
    ApiFetcher(const ApiFetcher&) = delete;
    ApiFetcher& operator=(const ApiFetcher&) = delete;

    // "http://HOST:PORT" for "ws://HOST:PORT/..." ("https://" for wss://); "" for anything else.
    static std::string http_base(const std::string& ws_url);

    // Starts GET path (starting with '/'), its answer's body at most max_body_bytes; false when
    // there is no server or kMaxInFlight requests are running.
    bool get(std::string key, const std::string& path, std::size_t max_body_bytes = 1U << 20U);
    // The answers that came since the last call, in the order they came.
    std::vector<Done> take_done();
    // A request with this key is running.
    bool running(const std::string& key) const;

private:
    struct Pending {
        std::string key;
        std::future<ApiAnswer> answer;
    };
    std::string base_;
    std::string ca_file_;
    std::vector<Pending> pending_;
};

} // namespace carrom::client::app
