#pragma once
// The client's only view of the network: a link that sends client messages and hands over the
// server messages received so far. The WebSocket implementation lives in net/ (carrom_net); the
// demo mode and the tests provide their own links. Everything here is called from the UI thread.

#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace carrom::client {

enum class LinkState {
    Connecting, // resolving, connecting, WebSocket handshake
    Open,       // messages flow
    Closed,     // closed by either side or lost; `detail` says why in plain words
};

struct LinkStatus {
    LinkState state = LinkState::Connecting;
    std::string detail; // e.g. "Could not reach 10.0.0.5:7777: connection refused."
    int close_code =
        0; // the server's close frame's code once Closed by it (4002: replaced), else 0
};

class MessageLink {
public:
    virtual ~MessageLink() = default;
    // Queues a message; messages sent while not open are dropped.
    virtual void send(const proto::ClientMessage& message) = 0;
    // Server messages received since the last poll, in arrival order. A frame that fails to
    // decode is not a message: the link reports it through on its status detail and goes on.
    virtual std::vector<proto::ServerMessage> poll() = 0;
    virtual LinkStatus status() const = 0;
    // Closes politely (a "leave" is the caller's business); status becomes Closed.
    virtual void close() = 0;
};

// Opens a new link to `url` (the server address the player gave, or where a redirect sends the
// session; called again to reconnect after a drop).
using LinkFactory = std::function<std::unique_ptr<MessageLink>(const std::string& url)>;

} // namespace carrom::client
