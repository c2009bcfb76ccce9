#include "store/match_ownership.hpp"

namespace carrom::store {

void MatchOwnership::set_on_lost(OnLost on_lost) {
    const std::lock_guard lock(mutex_);
    on_lost_ = std::move(on_lost);
}

void MatchOwnership::add(const MatchId& match, Owned owned) {
    const std::lock_guard lock(mutex_);
    owned_[match] = std::move(owned);
}

std::optional<MatchOwnership::Owned> MatchOwnership::find(const MatchId& match) const {
    const std::lock_guard lock(mutex_);
    const auto it = owned_.find(match);
    if (it == owned_.end()) {
        return std::nullopt;
    }
    return it->second;
}

void MatchOwnership::finished(const MatchId& match) {
    const std::lock_guard lock(mutex_);
    owned_.erase(match);
}

void MatchOwnership::lost(const MatchId& match) {
    OnLost on_lost;
    std::string room_code;
    {
        const std::lock_guard lock(mutex_);
        const auto it = owned_.find(match);
        if (it == owned_.end()) {
            return; // told already (or finished)
        }
        room_code = it->second.room_code;
        owned_.erase(it);
        ++lost_total_;
        on_lost = on_lost_;
    }
    if (on_lost) {
        on_lost(match, room_code);
    }
}

std::vector<std::pair<MatchId, MatchOwnership::Owned>> MatchOwnership::all() const {
    const std::lock_guard lock(mutex_);
    return {owned_.begin(), owned_.end()};
}

std::size_t MatchOwnership::size() const {
    const std::lock_guard lock(mutex_);
    return owned_.size();
}

std::uint64_t MatchOwnership::lost_total() const {
    const std::lock_guard lock(mutex_);
    return lost_total_;
}

} // namespace carrom::store
