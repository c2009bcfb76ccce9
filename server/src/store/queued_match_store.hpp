#pragma once
// The MatchStore writes every backend shares: create, append, set_seat_token, mark_finished,
// save_player and set_rated_seat queue a WriteItem on a StoreWriteQueue (store_write_queue.hpp)
// and return; flush and health are the queue's. A backend derives from it, implements the reads,
// and gives start_writing the function that writes one batch in one transaction on the queue's
// writer thread.

#include "store/match_store.hpp"
#include "store/store_options.hpp"
#include "store/store_write_queue.hpp"

#include <memory>
#include <string>
#include <string_view>

namespace carrom::store {

class QueuedMatchStore : public MatchStore {
public:
    void create(proto::MatchCreated created) override;
    void append(const MatchId& match, std::int64_t seq, proto::JournalEntry entry,
                OnWritten on_written = {}) override;
    void set_seat_token(const MatchId& match, int seat, std::optional<TokenHash> token) override;
    void mark_finished(const MatchId& match, std::int64_t time_ms) override;
    void save_player(IdentifiedPlayer player) override;
    void set_rated_seat(const MatchId& match, int seat, PlayerKeyHash player) override;
    bool flush(std::chrono::milliseconds timeout) override;
    StoreHealth health() const override;

protected:
    explicit QueuedMatchStore(std::string_view backend) : backend_(backend) {}
    // Starts the writer thread. Call once, when write_batch's connection is ready.
    void start_writing(std::string name, const StoreOptions& options,
                       StoreWriteQueue::WriteBatch write_batch,
                       std::function<void()> after_commit = {});
    // Writes what is queued (up to close_timeout) and joins the writer: a derived class calls it
    // first in its destructor, before the connection write_batch uses goes.
    void stop_writing();
    // A failure outside the writer's transactions, counted in health().errors_total.
    void count_error();

private:
    std::string backend_;
    std::unique_ptr<StoreWriteQueue> queue_;
};

} // namespace carrom::store
