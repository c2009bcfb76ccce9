#pragma once
// Private to server/src: the thread that answers the match API (match_api.hpp), so that a slow
// store read never runs on an I/O thread. One thread takes the queued requests in order and
// answers each through its callback, on the reader thread; at most max_pending requests wait
// (the HTTP session answers 503 store_busy beyond that). Boost-free.

#include "match_api.hpp"

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace carrom::server {

inline constexpr std::size_t kMatchApiMaxPending = 64;

class MatchApiReader {
public:
    // Called on the reader thread with the answer; keep it short (post it to the session).
    using Answered = std::function<void(MatchApiAnswer)>;

    MatchApiReader(std::shared_ptr<store::MatchStore> store, std::size_t max_pending);
    ~MatchApiReader(); // stop()
    MatchApiReader(const MatchApiReader&) = delete;
    MatchApiReader& operator=(const MatchApiReader&) = delete;

    // Queues the answer to a GET of target; false (nothing queued, answered never called) when
    // max_pending requests wait already or the reader is stopped.
    bool submit(std::string target, Answered answered);
    // Ends the thread once the read in progress is answered; the waiting requests are dropped
    // unanswered (their callbacks destroyed here). Idempotent.
    void stop();

private:
    struct Request {
        std::string target;
        Answered answered;
    };
    void run();

    std::shared_ptr<store::MatchStore> store_;
    std::size_t max_pending_;
    std::mutex mutex_;
    std::condition_variable cv_;
    std::deque<Request> queue_;
    bool stopping_ = false;
    std::thread thread_;
};

} // namespace carrom::server
