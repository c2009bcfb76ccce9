#pragma once
// Identified players and their ratings as the store keeps them (docs/ratings.md): plain data,
// backend-neutral. A player is its key's hash; the key itself is never stored.

#include "carrom/ratings/rating.hpp"
#include "carrom/rules/rule_set.hpp"
#include "store/sha256.hpp"

#include <cstdint>
#include <string>

namespace carrom::store {

// sha256 of the player's identity key as sent (64 lowercase hex digits).
using PlayerKeyHash = Sha256Digest;

struct IdentifiedPlayer {
    PlayerKeyHash key_hash{};
    std::string name;            // as the player last chose it
    std::string name_key;        // the name's comparison key (player_name_key.hpp), unique
    std::int64_t created_ms = 0; // Unix time of the first hello with this key
    friend bool operator==(const IdentifiedPlayer&, const IdentifiedPlayer&) = default;
};

struct PlayerRating {
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    ratings::Rating rating{}; // as of the last rated game (not aged: see docs/ratings.md)
    int games = 0;
    int wins = 0;
    int losses = 0;
    int draws = 0;
    std::int64_t last_game_ms = 0; // Unix time of the last rated game
    friend bool operator==(const PlayerRating&, const PlayerRating&) = default;
};

// MatchStore::leaderboard's limit is clamped to 1..this.
inline constexpr int kMaxLeaderboardRows = 100;

struct LeaderboardRow {
    std::string name;
    PlayerRating rating;
};

} // namespace carrom::store
