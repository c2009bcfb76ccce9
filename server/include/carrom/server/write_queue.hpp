#pragma once
// One session's outgoing messages: at most one write in flight, a bound on queued bytes, and
// snapshot dropping under back-pressure. Not thread-safe (lives on the session's strand).

#include "carrom/server/peer.hpp"

#include <cstddef>
#include <deque>
#include <optional>

namespace carrom::server {

class WriteQueue {
public:
    // A snapshot is dropped while `snapshot_backlog` or more snapshots wait (not counting the
    // one in flight): the client is then that many frames of motion behind. Other messages
    // (events, room state) never count toward it, so a burst of physics events at a break does
    // not cost a fast client its snapshots. Once queued bytes would exceed max_bytes the queue
    // overflows (the session disconnects the slow client).
    WriteQueue(std::size_t max_bytes, std::size_t snapshot_backlog);

    enum class Push { Queued, DroppedSnapshot, Overflow };
    Push push(Outgoing message);

    // The next message to write, if none is in flight; marks it in flight.
    std::optional<Outgoing> start_write();
    // The in-flight write finished.
    void finish_write();

    bool writing() const { return writing_; }
    bool empty() const { return queue_.empty() && !writing_; }
    std::size_t queued_messages() const { return queue_.size(); }
    std::size_t queued_bytes() const { return bytes_; }
    // Snapshots queued and not in flight.
    std::size_t waiting_snapshots() const;

private:
    std::size_t max_bytes_;
    std::size_t snapshot_backlog_;
    std::deque<Outgoing> queue_; // front is in flight while writing_
    std::size_t bytes_ = 0;
    std::size_t snapshots_ = 0; // snapshots in queue_, the one in flight included
    bool writing_ = false;
};

} // namespace carrom::server
