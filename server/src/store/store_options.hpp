#pragma once
// How a MatchStore backend queues, batches and retries its writes (store_write_queue.hpp), and the
// test seams every backend has. Durations are wall-clock time on a steady clock.

#include <chrono>
#include <cstddef>
#include <functional>

namespace carrom::store {

struct StoreOptions {
    std::size_t max_batch = 512;      // items per transaction
    std::size_t max_pending = 200000; // items held (queued or failing); more are dropped
    std::chrono::milliseconds retry_initial{100};
    std::chrono::milliseconds retry_max{5000};
    std::chrono::milliseconds checkpoint_interval{1000}; // SQLite only: WAL checkpoints
    std::chrono::milliseconds close_timeout{5000};       // the destructor's time to write the queue
    std::chrono::milliseconds log_interval{10000}; // at most one write-error line per interval
    // Test seam: while it returns true, every transaction fails just before its COMMIT and is
    // rolled back, as a real write error would be. Called on the writer thread.
    std::function<bool()> fail_writes;
    // Test seam: called before each journal and recent_matches read, on the reading thread (it
    // may block, to make a read slow).
    std::function<void()> before_read;
};

} // namespace carrom::store
