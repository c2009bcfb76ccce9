#pragma once
// One session's outgoing messages: at most one write in flight, a bound on queued bytes, and
// snapshot dropping under back-pressure. Not thread-safe (lives on the session's strand).

#include "carrom/room/peer.hpp"

#include <cstddef>
#include <deque>

namespace carrom::server {

class WriteQueue {
public:
    // A snapshot is dropped while `snapshot_backlog` or more snapshots wait (not counting the
    // one in flight): the client is then that many frames of motion behind. Other messages
    // never count toward it, so a burst of collision cues at a break does not cost a fast
    // client its snapshots. A cue is dropped while the client is that far behind, or while
    // `cue_backlog` cues already wait (a cascade of collisions in one instant). Once queued
    // bytes would exceed max_bytes the queue overflows (the session disconnects the slow
    // client). A room state replaces every room state still waiting: the newer one describes the
    // whole room, so superseded states neither pile up nor push a player over the bound.
    WriteQueue(std::size_t max_bytes, std::size_t snapshot_backlog, std::size_t cue_backlog = 64);

    enum class Push { Queued, DroppedSnapshot, DroppedCue, Overflow };
    Push push(room::Outgoing message);

    // The next message to write, if none is in flight (else null); marks it in flight. It stays
    // in the queue, and the pointer valid, until finish_write: the writer copies nothing.
    const room::Outgoing* start_write();
    // The in-flight write finished.
    void finish_write();
    // Forgets every message not yet in flight (a session closing a slow client keeps only the
    // write in progress, so that the close frame follows it).
    void drop_waiting();

    bool writing() const { return writing_; }
    bool empty() const { return queue_.empty() && !writing_; }
    std::size_t queued_messages() const { return queue_.size(); }
    std::size_t queued_bytes() const { return bytes_; }
    // Snapshots (cues) queued and not in flight.
    std::size_t waiting_snapshots() const;
    std::size_t waiting_cues() const;

private:
    // 1 when the message in flight is of this kind, else 0.
    std::size_t in_flight(room::MessageKind kind) const;
    // Forgets the room states not yet in flight (a newer one is being queued).
    void drop_waiting_states();
    // Counts a queued (added) or finished (removed) message in snapshots_ or cues_.
    void count(room::MessageKind kind, bool added);

    std::size_t max_bytes_;
    std::size_t snapshot_backlog_;
    std::size_t cue_backlog_;
    std::deque<room::Outgoing> queue_; // front is in flight while writing_
    std::size_t bytes_ = 0;
    std::size_t snapshots_ = 0; // snapshots in queue_, the one in flight included
    std::size_t cues_ = 0;      // cues in queue_, the one in flight included
    bool writing_ = false;
};

} // namespace carrom::server
