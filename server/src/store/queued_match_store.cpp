#include "store/queued_match_store.hpp"

namespace carrom::store {

void QueuedMatchStore::start_writing(std::string name, const StoreOptions& options,
                                     StoreWriteQueue::WriteBatch write_batch,
                                     std::function<void()> after_commit) {
    queue_ = std::make_unique<StoreWriteQueue>(std::move(name), options, std::move(write_batch),
                                               std::move(after_commit));
    queue_->start();
}

void QueuedMatchStore::stop_writing() {
    if (queue_) {
        queue_->stop();
    }
}

void QueuedMatchStore::count_error() {
    queue_->count_error();
}

void QueuedMatchStore::create(proto::MatchCreated created) {
    queue_->enqueue(WriteItem{CreateItem{std::move(created)}, {}});
}

void QueuedMatchStore::append(const MatchId& match, std::int64_t seq, proto::JournalEntry entry,
                              OnWritten on_written) {
    queue_->enqueue(WriteItem{AppendItem{match, seq, std::move(entry)}, std::move(on_written)});
}

void QueuedMatchStore::set_seat_token(const MatchId& match, int seat,
                                      std::optional<TokenHash> token) {
    queue_->enqueue(WriteItem{SeatTokenItem{match, seat, token}, {}});
}

void QueuedMatchStore::mark_finished(const MatchId& match, std::int64_t time_ms) {
    queue_->enqueue(WriteItem{FinishItem{match, time_ms}, {}});
}

void QueuedMatchStore::save_player(IdentifiedPlayer player) {
    queue_->enqueue(WriteItem{PlayerItem{std::move(player)}, {}});
}

void QueuedMatchStore::set_rated_seat(const MatchId& match, int seat, PlayerKeyHash player) {
    queue_->enqueue(WriteItem{RatedSeatItem{match, seat, player}, {}});
}

bool QueuedMatchStore::flush(std::chrono::milliseconds timeout) {
    return queue_->flush(timeout);
}

StoreHealth QueuedMatchStore::health() const {
    StoreHealth h = queue_->health();
    h.backend = backend_;
    return h;
}

} // namespace carrom::store
