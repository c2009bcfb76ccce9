#include "rated_queue.hpp"

#include "carrom/ratings/rating_window.hpp"

#include <algorithm>

namespace carrom::server {

RatedQueue::Added RatedQueue::add(proto::RuleSet rule_set, Entry entry) {
    const std::lock_guard lock(mutex_);
    auto& queue = queues_[rule_set];
    for (const Entry& e : queue) {
        if (e.player_id == entry.player_id) {
            return Added::AlreadyQueued;
        }
        if (e.key_hash == entry.key_hash) {
            return Added::SameIdentityWaiting;
        }
    }
    queue.push_back(std::move(entry));
    return Added::Queued;
}

std::optional<std::pair<RatedQueue::Waiter, RatedQueue::Waiter>>
RatedQueue::pair(proto::RuleSet rule_set, std::int64_t now_ms) {
    const std::lock_guard lock(mutex_);
    auto& queue = queues_[rule_set];
    std::erase_if(queue, [](const Entry& e) { return e.waiter.expired(); });
    std::vector<ratings::WaitingPlayer> waiting;
    waiting.reserve(queue.size());
    for (const Entry& e : queue) {
        waiting.push_back({e.rating, static_cast<double>(now_ms - e.since_ms) / 1000.0});
    }
    const auto chosen = ratings::closest_acceptable_pair(waiting);
    if (!chosen) {
        return std::nullopt;
    }
    std::pair<Waiter, Waiter> out{queue[chosen->first].waiter, queue[chosen->second].waiter};
    queue.erase(queue.begin() + static_cast<std::ptrdiff_t>(chosen->second));
    queue.erase(queue.begin() + static_cast<std::ptrdiff_t>(chosen->first));
    return out;
}

bool RatedQueue::remove(std::int64_t player_id) {
    const std::lock_guard lock(mutex_);
    std::size_t removed = 0;
    for (auto& [rule_set, queue] : queues_) {
        removed += std::erase_if(queue, [&](const Entry& e) { return e.player_id == player_id; });
    }
    return removed > 0;
}

std::size_t RatedQueue::waiting_count() const {
    const std::lock_guard lock(mutex_);
    std::size_t n = 0;
    for (const auto& [rule_set, queue] : queues_) {
        n += queue.size();
    }
    return n;
}

} // namespace carrom::server
