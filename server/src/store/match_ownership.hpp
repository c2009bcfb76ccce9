#pragma once
// The matches one cluster instance owns (docs/cluster.md, "Ownership"): for each, the ownership
// epoch it holds (matches.owner_epoch) and its room code. Filled by the store's writer when a
// match it creates is committed, and by the cluster thread when it claims one; emptied when the
// match finishes or is lost. Thread-safe (one mutex, short critical sections).

#include "store/match_store.hpp"

#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace carrom::store {

class MatchOwnership {
public:
    struct Owned {
        std::int64_t epoch = 0;
        std::string room_code;
    };
    using OnLost = std::function<void(const MatchId& match, const std::string& room_code)>;

    void set_on_lost(OnLost on_lost);

    void add(const MatchId& match, Owned owned);
    std::optional<Owned> find(const MatchId& match) const;
    // The match finished: no longer owned (and not lost).
    void finished(const MatchId& match);
    // Another instance claimed the match: forgotten, counted, and on_lost called once.
    void lost(const MatchId& match);
    std::vector<std::pair<MatchId, Owned>> all() const;
    std::size_t size() const;
    std::uint64_t lost_total() const;

private:
    mutable std::mutex mutex_;
    std::unordered_map<MatchId, Owned> owned_;
    std::uint64_t lost_total_ = 0;
    OnLost on_lost_;
};

} // namespace carrom::store
