#include "store/store_write_queue.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <exception>

namespace carrom::store {

using Clock = std::chrono::steady_clock;

StoreWriteQueue::StoreWriteQueue(std::string name, const StoreOptions& options,
                                 WriteBatch write_batch, std::function<void()> after_commit)
    : name_(std::move(name)), options_(options), write_batch_(std::move(write_batch)),
      after_commit_(std::move(after_commit)) {
    options_.max_batch = std::max<std::size_t>(options_.max_batch, 1);
}

StoreWriteQueue::~StoreWriteQueue() {
    stop();
}

void StoreWriteQueue::start() {
    writer_ = std::thread([this] { writer_loop(); });
}

void StoreWriteQueue::stop() {
    {
        const std::lock_guard lock(mutex_);
        if (!stopping_) {
            stopping_ = true;
            stop_deadline_ = Clock::now() + options_.close_timeout;
        }
    }
    work_cv_.notify_all();
    if (writer_.joinable()) {
        writer_.join();
    }
}

void StoreWriteQueue::enqueue(WriteItem item) {
    {
        const std::lock_guard lock(mutex_);
        if (queue_.size() + in_flight_ < options_.max_pending && !stopping_) {
            queue_.push_back(std::move(item));
            ++queued_total_;
            work_cv_.notify_one();
            return;
        }
    }
    const std::uint64_t drops = dropped_total_.fetch_add(1, std::memory_order_relaxed) + 1;
    errors_total_.fetch_add(1, std::memory_order_relaxed);
    if (drops % 10000 == 1) { // the first, then one line per 10,000
        spdlog::error("store {}: {} items wait to be written; new items are dropped ({} so far)",
                      name_, options_.max_pending, drops);
    }
    if (item.on_written) {
        item.on_written(false);
    }
}

bool StoreWriteQueue::flush(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    const std::uint64_t target = queued_total_;
    return done_cv_.wait_for(lock, timeout, [&] { return done_total_ >= target; });
}

void StoreWriteQueue::writer_loop() {
    std::deque<WriteItem> batch; // taken from the queue; failed items stay here, in order
    auto backoff = options_.retry_initial;
    for (;;) {
        {
            std::unique_lock lock(mutex_);
            if (batch.empty()) {
                work_cv_.wait(lock, [&] { return !queue_.empty() || stopping_; });
                if (queue_.empty()) {
                    return; // stopping, and everything is written
                }
            }
            while (!queue_.empty() && batch.size() < options_.max_batch) {
                batch.push_back(std::move(queue_.front()));
                queue_.pop_front();
                ++in_flight_;
            }
        }
        if (write(batch)) {
            backoff = options_.retry_initial;
            continue;
        }
        std::unique_lock lock(mutex_);
        if (stopping_ && Clock::now() >= stop_deadline_) {
            const std::size_t lost = batch.size() + queue_.size();
            spdlog::error("store {}: stopping with {} items not written ({})", name_, lost,
                          last_error_);
            dropped_total_.fetch_add(lost, std::memory_order_relaxed);
            done_total_ += lost;
            in_flight_ = 0;
            queue_.clear();
            done_cv_.notify_all();
            return;
        }
        // Sleep (new items still queue meanwhile); while stopping, not past the deadline.
        const auto wake =
            std::min(Clock::now() + backoff, stopping_ ? stop_deadline_ : Clock::time_point::max());
        work_cv_.wait_until(lock, wake, [&] { return Clock::now() >= wake; });
        backoff = std::min(backoff * 2, options_.retry_max);
    }
}

bool StoreWriteQueue::write(std::deque<WriteItem>& batch) {
    std::vector<WriteItem> items(std::make_move_iterator(batch.begin()),
                                 std::make_move_iterator(batch.end()));
    batch.clear();
    std::vector<WriteRefusal> refused;
    std::string error;
    try {
        refused = write_batch_(items);
    } catch (const std::exception& e) {
        error = e.what();
        if (error.empty()) {
            error = "unknown error";
        }
        std::replace(error.begin(), error.end(), '\n', ' '); // one line
    }
    if (!error.empty()) {
        // Nothing was written: every item is kept for the retry; its caller waits for it (a
        // room's stroke streams only once written, docs/cluster.md "The database down").
        std::size_t waiting = 0;
        {
            const std::lock_guard lock(mutex_);
            degraded_ = true;
            last_error_ = error;
            waiting = items.size() + queue_.size();
        }
        errors_total_.fetch_add(1, std::memory_order_relaxed);
        report_failure(error, waiting);
        batch.assign(std::make_move_iterator(items.begin()), std::make_move_iterator(items.end()));
        return false;
    }
    std::vector<bool> dropped(items.size(), false);
    std::size_t invalid = 0; // refused as invalid (errors); the others are of a lost match
    for (const auto& r : refused) {
        if (!r.lost) {
            spdlog::error("store {}: an item was refused and dropped: {}", name_, r.reason);
            ++invalid;
        }
        dropped[r.index] = true;
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].on_written) {
            items[i].on_written(!dropped[i]);
        }
    }
    const std::size_t written = items.size() - refused.size();
    written_total_.fetch_add(written, std::memory_order_relaxed);
    dropped_total_.fetch_add(refused.size(), std::memory_order_relaxed);
    errors_total_.fetch_add(invalid, std::memory_order_relaxed);
    if (after_commit_) {
        after_commit_();
    }
    if (failures_in_outage_ > 0) {
        spdlog::info("store {}: writing again after {} failed attempts", name_,
                     failures_in_outage_);
        failures_in_outage_ = 0;
        failures_since_log_ = 0;
        last_log_.reset();
    }
    {
        const std::lock_guard lock(mutex_);
        degraded_ = false;
        in_flight_ -= items.size();
        done_total_ += items.size();
    }
    done_cv_.notify_all();
    return true;
}

void StoreWriteQueue::report_failure(const std::string& error, std::size_t waiting) {
    ++failures_in_outage_;
    ++failures_since_log_;
    const auto now = Clock::now();
    if (last_log_ && now - *last_log_ < options_.log_interval) {
        return;
    }
    spdlog::warn("store {}: writing failed ({} failed attempts since the last report): {}; {} "
                 "items wait in memory and are retried",
                 name_, failures_since_log_, error, waiting);
    last_log_ = now;
    failures_since_log_ = 0;
}

StoreHealth StoreWriteQueue::health() const {
    StoreHealth h;
    h.errors_total = errors_total_.load(std::memory_order_relaxed);
    h.dropped_total = dropped_total_.load(std::memory_order_relaxed);
    h.written_total = written_total_.load(std::memory_order_relaxed);
    const std::lock_guard lock(mutex_);
    h.degraded = degraded_;
    h.pending = queue_.size() + in_flight_;
    h.last_error = last_error_;
    return h;
}

} // namespace carrom::store
