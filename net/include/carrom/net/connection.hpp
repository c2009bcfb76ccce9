#pragma once
// A WebSocket client connection to a carrom server, shared by carrom-client and carrom-bot.
// It runs its own I/O thread (Boost.Beast, kept out of this header); every member function is
// thread-safe. Messages are proto structs: the connection encodes what it sends and decodes and
// validates what it receives.

#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace carrom::net {

enum class ConnectionState {
    Connecting, // resolving, TCP connect, WebSocket handshake
    Open,       // messages flow
    Closed,     // closed by either side, refused or lost; detail says why in plain words
};

struct ConnectionStatus {
    ConnectionState state = ConnectionState::Connecting;
    std::string detail; // e.g. "Could not reach 127.0.0.1:7777: connection refused."
    // The close code of the server's close frame once Closed by the server (1012: the server is
    // restarting); 0 when the connection ended without one (refused, lost, closed by us).
    int close_code = 0;
};

struct ConnectionOptions {
    std::chrono::milliseconds connect_timeout{5000};
    // Once open: when nothing (not even a pong) has arrived for half of this, the connection
    // pings the server; when nothing has arrived for all of it, the link is taken for dead
    // (a cable pulled, Wi-Fi gone: no reset ever arrives) and the connection closes with a
    // sentence saying so. Zero: wait forever.
    std::chrono::milliseconds silence_timeout{10000};
    std::size_t max_queued_sends = 256; // sends beyond this while the socket is slow are dropped
    // wss://: a PEM file of certificate authorities trusted besides the system's (a private CA);
    // empty: the system's only. The server's certificate is always verified.
    std::string ca_file;
};

class Connection {
public:
    // Starts connecting to url (ws:// or wss://HOST:PORT[/path]) at once; never throws. A malformed
    // url gives a connection that is Closed with the reason in detail.
    static std::unique_ptr<Connection> open(const std::string& url,
                                            const ConnectionOptions& options = {});
    virtual ~Connection() = default; // closes and joins the I/O thread

    // Queues a message; sent once the connection opens, dropped once it is closed.
    virtual void send(const proto::ClientMessage& message) = 0;
    // Queues raw text as one text frame, unvalidated (for tests of the server's input checks).
    virtual void send_text(const std::string& text) = 0;
    // Messages received since the last call, in arrival order. A frame that fails to decode is
    // skipped and counted in decode_errors().
    virtual std::vector<proto::ServerMessage> poll() = 0;
    // Blocks until a message is waiting, the state changes, or the timeout passes. Returns true
    // if a message is waiting.
    virtual bool wait(std::chrono::milliseconds timeout) = 0;
    virtual ConnectionStatus status() const = 0;
    virtual int decode_errors() const = 0;
    // Sends a WebSocket close frame and ends the connection; status becomes Closed.
    virtual void close() = 0;
};

} // namespace carrom::net
