#include "match_api_reader.hpp"

#include <utility>

namespace carrom::server {

MatchApiReader::MatchApiReader(std::shared_ptr<store::MatchStore> store, std::size_t max_pending)
    : store_(std::move(store)), max_pending_(max_pending), thread_([this] { run(); }) {}

MatchApiReader::~MatchApiReader() {
    stop();
}

bool MatchApiReader::submit(std::string target, Answered answered) {
    {
        const std::lock_guard lock(mutex_);
        if (stopping_ || queue_.size() >= max_pending_) {
            return false;
        }
        queue_.push_back(Request{std::move(target), std::move(answered)});
    }
    cv_.notify_one();
    return true;
}

void MatchApiReader::stop() {
    std::deque<Request> dropped;
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
        dropped.swap(queue_);
    }
    cv_.notify_all();
    if (thread_.joinable()) {
        thread_.join();
    }
    dropped.clear(); // outside the lock: a callback's captures may do work when destroyed
}

void MatchApiReader::run() {
    for (;;) {
        Request request;
        {
            std::unique_lock lock(mutex_);
            cv_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
            if (stopping_) {
                return;
            }
            request = std::move(queue_.front());
            queue_.pop_front();
        }
        request.answered(answer_match_api(store_.get(), request.target));
    }
}

} // namespace carrom::server
