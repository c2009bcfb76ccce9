#include "carrom/server/write_queue.hpp"

namespace carrom::server {

WriteQueue::WriteQueue(std::size_t max_bytes, std::size_t snapshot_backlog)
    : max_bytes_(max_bytes), snapshot_backlog_(snapshot_backlog) {}

std::size_t WriteQueue::waiting_snapshots() const {
    const bool in_flight_snapshot =
        writing_ && !queue_.empty() && queue_.front().kind == MessageKind::Snapshot;
    return snapshots_ - (in_flight_snapshot ? 1U : 0U);
}

WriteQueue::Push WriteQueue::push(Outgoing message) {
    const bool snapshot = message.kind == MessageKind::Snapshot;
    if (snapshot && waiting_snapshots() >= snapshot_backlog_) {
        return Push::DroppedSnapshot;
    }
    const std::size_t size = message.text ? message.text->size() : 0;
    if (bytes_ + size > max_bytes_) {
        return Push::Overflow;
    }
    bytes_ += size;
    snapshots_ += snapshot ? 1U : 0U;
    queue_.push_back(std::move(message));
    return Push::Queued;
}

std::optional<Outgoing> WriteQueue::start_write() {
    if (writing_ || queue_.empty()) {
        return std::nullopt;
    }
    writing_ = true;
    return queue_.front();
}

void WriteQueue::finish_write() {
    if (!writing_ || queue_.empty()) {
        return;
    }
    const std::size_t size = queue_.front().text ? queue_.front().text->size() : 0;
    bytes_ -= size;
    snapshots_ -= queue_.front().kind == MessageKind::Snapshot ? 1U : 0U;
    queue_.pop_front();
    writing_ = false;
}

} // namespace carrom::server
