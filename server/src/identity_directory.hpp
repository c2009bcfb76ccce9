#pragma once
// Private to server/src: the identified players this server knows (docs/ratings.md), in memory,
// loaded from the store at start and kept in step with it (the caller queues save_player for
// every claim that changed something). One server owns its store file, so this map decides:
// a name (compared by player_name_key) belongs to at most one identity, and a guest may not use
// it either. New identities are limited per client address. Thread-safe (one mutex).
// Boost-free.

#include "address_rate_limiter.hpp"

#include "carrom/proto/error.hpp"
#include "store/player_records.hpp"

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace carrom::server {

// New identities from one address: kNewIdentitiesPerMinute a minute sustained, bursts of as
// many (docs/ratings.md, "Abuse").
inline constexpr double kNewIdentitiesPerMinute = 5.0;
inline constexpr std::size_t kNewIdentityAddresses = 10000; // addresses tracked at once

class IdentityDirectory {
public:
    IdentityDirectory();

    // Replaces the directory's players (the store's, at start).
    void load(const std::vector<store::IdentifiedPlayer>& players);

    struct Claimed {
        store::IdentifiedPlayer player;
        bool changed = false; // new, or renamed: the store must save it
    };
    // The holder of key_hash says hello with name: the player (created on its first hello,
    // renamed when the name differs), or name_taken (another identity holds the name),
    // too_many_identities (a new key from an address over its limit) or bad_field (a name with
    // no comparable character). now_ms: wall clock (created_ms); monotonic_ms: the rate limit's.
    std::variant<Claimed, proto::Error> claim(const store::PlayerKeyHash& key_hash,
                                              const std::string& name, const std::string& address,
                                              std::int64_t now_ms, std::int64_t monotonic_ms);
    // A guest's name: name_taken when an identity holds it.
    std::optional<proto::Error> check_guest_name(const std::string& name) const;
    std::optional<store::IdentifiedPlayer> find(const store::PlayerKeyHash& key_hash) const;
    std::size_t size() const;

private:
    mutable std::mutex mutex_;
    std::unordered_map<std::string, store::IdentifiedPlayer> by_key_; // hex key hash -> player
    std::unordered_map<std::string, std::string> key_by_name_;        // name key -> hex key hash
    AddressRateLimiter new_identities_;
};

} // namespace carrom::server
