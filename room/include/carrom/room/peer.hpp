#pragma once
// What a room sees of a connected client: a thread-safe mailbox. The server's WebSocket session
// implements it; the client's offline demo has a local one; tests use a recording fake.

#include <cstdint>
#include <memory>
#include <string>

namespace carrom::room {

enum class MessageKind : std::uint8_t {
    Normal,   // must be delivered (or the client is disconnected)
    Snapshot, // a delta snapshot: may be dropped under back-pressure (then a keyframe follows)
    Cue,      // only useful while fresh (a collision's sound, the opponent's aim): dropped, with
              // no keyframe, while the client is behind; never counted as a snapshot
    State,    // a broadcast room_state: a newer one replaces one still waiting to be sent
};

struct Outgoing {
    std::shared_ptr<const std::string> text; // shared by every receiver of a broadcast
    MessageKind kind = MessageKind::Normal;
};

class Peer {
public:
    virtual ~Peer() = default;
    virtual std::int64_t player_id() const = 0;
    virtual const std::string& name() const = 0;
    // The token that resumes this player's seat ("" if none): the room hands it to its journal
    // sink, which stores only a hash of it.
    virtual std::string resume_token() const { return {}; }
    // Queues a message. Thread-safe; never blocks.
    virtual void send(Outgoing message) = 0;
    // True once after the session dropped a snapshot: the next snapshot it gets must be a
    // keyframe. Thread-safe.
    virtual bool take_keyframe_request() = 0;
    // Sends the queued messages, then closes with the code. Thread-safe.
    virtual void close(int close_code, std::string reason) = 0;
};

} // namespace carrom::room
