#pragma once
// The write side every MatchStore backend shares: a queue of WriteItems that callers fill without
// blocking, and one writer thread that hands them, in order, up to max_batch at a time, to the
// backend's write_batch (one transaction).
//
// Threads: callers only queue (a mutex held for a push). The writer thread is the only one that
// calls write_batch, so a backend's write connection needs no lock of its own.
//
// Failures: a write_batch that throws wrote nothing (its transaction was rolled back); its items
// stay in memory, in order, in front of everything queued after them, and are retried with
// exponential backoff (retry_initial doubling up to retry_max). Until a retry succeeds the store
// is degraded (health()); every failed attempt counts in errors_total; the log gets one line at
// the first failure and at most one per log_interval after it, and one when writing resumes.
// Items beyond max_pending are dropped (counted). An item write_batch refuses as invalid (an
// append to a match never created, a seq written twice) is dropped and counted too.
// An item of a match another cluster instance owns (WriteRefusal::lost) is dropped and counted
// as dropped, not as an error, and not logged here (the store reports the match lost).

#include "store/match_store.hpp"
#include "store/store_options.hpp"
#include "store/write_item.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace carrom::store {

class StoreWriteQueue {
public:
    // Writes the items in one transaction and returns those it left out as invalid; throws (any
    // std::exception) when the transaction failed and nothing was written.
    using WriteBatch = std::function<std::vector<WriteRefusal>(std::span<WriteItem>)>;

    // name: how log lines name the store (a path, or a URL without its password).
    StoreWriteQueue(std::string name, const StoreOptions& options, WriteBatch write_batch,
                    std::function<void()> after_commit = {});
    // stop().
    ~StoreWriteQueue();
    StoreWriteQueue(const StoreWriteQueue&) = delete;
    StoreWriteQueue& operator=(const StoreWriteQueue&) = delete;

    void start();
    // Writes what is queued (for up to close_timeout; then what is left is dropped and counted)
    // and joins the writer thread. Idempotent.
    void stop();

    void enqueue(WriteItem item);
    // Waits until everything queued before the call is written or dropped.
    bool flush(std::chrono::milliseconds timeout);
    StoreHealth health() const;
    // A failure outside the writer's transactions (SQLite: a checkpoint), counted in errors_total.
    void count_error() { errors_total_.fetch_add(1, std::memory_order_relaxed); }

private:
    void writer_loop();
    // Writes batch; true on success. Tells callers, counts, logs.
    bool write(std::deque<WriteItem>& batch);
    void report_failure(const std::string& error, std::size_t waiting);

    std::string name_;
    StoreOptions options_;
    WriteBatch write_batch_;
    std::function<void()> after_commit_;

    mutable std::mutex mutex_;
    std::condition_variable work_cv_; // the writer waits for work (or stop)
    std::condition_variable done_cv_; // flush waits for progress
    std::deque<WriteItem> queue_;
    std::size_t in_flight_ = 0;      // items the writer holds
    std::uint64_t queued_total_ = 0; // items accepted by enqueue
    std::uint64_t done_total_ = 0;   // items written or dropped
    bool stopping_ = false;
    std::chrono::steady_clock::time_point stop_deadline_{};
    std::string last_error_;
    bool degraded_ = false;

    std::atomic<std::uint64_t> errors_total_{0};
    std::atomic<std::uint64_t> dropped_total_{0};
    std::atomic<std::uint64_t> written_total_{0};

    // Writer thread only: the rate limit of failure log lines.
    std::optional<std::chrono::steady_clock::time_point> last_log_;
    std::uint64_t failures_since_log_ = 0;
    std::uint64_t failures_in_outage_ = 0;

    std::thread writer_;
};

} // namespace carrom::store
