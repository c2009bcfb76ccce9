#pragma once
// Private to server/src: the quick-match queue of identified players in singles (docs/ratings.md,
// "Fair pairing"). Pairs by rating with ratings::closest_acceptable_pair, the acceptable gap
// widening with the time waited; one identity waits at most once. Thread-safe (one mutex).
// Boost-free.

#include "carrom/proto/types.hpp"
#include "store/player_records.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace carrom::server {

class WsSession;

class RatedQueue {
public:
    using Waiter = std::weak_ptr<WsSession>;

    struct Entry {
        std::int64_t player_id = 0;
        store::PlayerKeyHash key_hash{};
        double rating = 0.0;       // points
        std::int64_t since_ms = 0; // monotonic time the wait began
        Waiter waiter;
    };

    enum class Added { Queued, AlreadyQueued, SameIdentityWaiting };
    // Queues the entry for rule_set (a player already queued keeps its place).
    Added add(proto::RuleSet rule_set, Entry entry);
    // The closest acceptable pair of rule_set's queue at now_ms, taken out of the queue.
    std::optional<std::pair<Waiter, Waiter>> pair(proto::RuleSet rule_set, std::int64_t now_ms);
    // Takes the player out of every queue; true if it was waiting.
    bool remove(std::int64_t player_id);
    std::size_t waiting_count() const;

private:
    mutable std::mutex mutex_;
    std::map<proto::RuleSet, std::vector<Entry>> queues_; // longest-waiting first
};

} // namespace carrom::server
