#include "carrom/server/write_queue.hpp"

namespace carrom::server {

WriteQueue::WriteQueue(std::size_t max_bytes, std::size_t snapshot_backlog, std::size_t cue_backlog)
    : max_bytes_(max_bytes), snapshot_backlog_(snapshot_backlog), cue_backlog_(cue_backlog) {}

std::size_t WriteQueue::in_flight(room::MessageKind kind) const {
    return writing_ && !queue_.empty() && queue_.front().kind == kind ? 1U : 0U;
}

void WriteQueue::count(room::MessageKind kind, bool added) {
    if (kind != room::MessageKind::Snapshot && kind != room::MessageKind::Cue) {
        return;
    }
    std::size_t& counter = kind == room::MessageKind::Snapshot ? snapshots_ : cues_;
    counter = added ? counter + 1 : counter - 1;
}

std::size_t WriteQueue::waiting_snapshots() const {
    return snapshots_ - in_flight(room::MessageKind::Snapshot);
}

std::size_t WriteQueue::waiting_cues() const {
    return cues_ - in_flight(room::MessageKind::Cue);
}

WriteQueue::Push WriteQueue::push(room::Outgoing message) {
    const bool behind = waiting_snapshots() >= snapshot_backlog_;
    if (message.kind == room::MessageKind::Snapshot && behind) {
        return Push::DroppedSnapshot;
    }
    if (message.kind == room::MessageKind::Cue && (behind || waiting_cues() >= cue_backlog_)) {
        return Push::DroppedCue;
    }
    if (message.kind == room::MessageKind::State) {
        drop_waiting_states();
    }
    const std::size_t size = message.text ? message.text->size() : 0;
    if (bytes_ + size > max_bytes_) {
        return Push::Overflow;
    }
    bytes_ += size;
    count(message.kind, true);
    queue_.push_back(std::move(message));
    return Push::Queued;
}

const room::Outgoing* WriteQueue::start_write() {
    if (writing_ || queue_.empty()) {
        return nullptr;
    }
    writing_ = true;
    return &queue_.front();
}

void WriteQueue::finish_write() {
    if (!writing_ || queue_.empty()) {
        return;
    }
    const std::size_t size = queue_.front().text ? queue_.front().text->size() : 0;
    bytes_ -= size;
    count(queue_.front().kind, false);
    queue_.pop_front();
    writing_ = false;
}

void WriteQueue::drop_waiting_states() {
    const auto first_waiting = queue_.begin() + (writing_ && !queue_.empty() ? 1 : 0);
    for (auto it = first_waiting; it != queue_.end();) {
        if (it->kind == room::MessageKind::State) {
            bytes_ -= it->text ? it->text->size() : 0;
            it = queue_.erase(it);
        } else {
            ++it;
        }
    }
}

void WriteQueue::drop_waiting() {
    const std::size_t keep = writing_ && !queue_.empty() ? 1U : 0U;
    while (queue_.size() > keep) {
        const std::size_t size = queue_.back().text ? queue_.back().text->size() : 0;
        bytes_ -= size;
        count(queue_.back().kind, false);
        queue_.pop_back();
    }
}

} // namespace carrom::server
