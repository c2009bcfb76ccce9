#pragma once
// The server-wide registry, shared by all threads (one mutex, short critical sections): rooms by
// code (with the room limit), players by resume token, and the quick-match queues (one per rule
// set and seat count). It never
// touches a room's state; the room type is a parameter so tests can use a plain one.

#include "carrom/proto/error.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/server/random.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

namespace carrom::server {

struct PlayerRecord {
    std::int64_t player_id = 0;
    std::string token;
    std::string room_code; // the room the player last took a seat in ("" if none)
    // The sha256 of the player's identity key (docs/ratings.md); none for a guest.
    std::optional<std::array<std::uint8_t, 32>> identity = {};
};

template <class RoomT, class WaiterT> class Registry {
public:
    Registry(RandomSource& random, std::size_t max_rooms)
        : random_(random), max_rooms_(max_rooms) {}

    // --- players ---
    PlayerRecord new_player() {
        std::lock_guard lock(mutex_);
        PlayerRecord record;
        record.player_id = next_player_id_++;
        do {
            record.token = make_resume_token(random_);
        } while (players_.count(record.token) != 0);
        players_[record.token] = record;
        return record;
    }
    std::optional<PlayerRecord> find_player(const std::string& token) const {
        std::lock_guard lock(mutex_);
        const auto it = players_.find(token);
        if (it == players_.end()) {
            return std::nullopt;
        }
        return it->second;
    }
    void set_player_room(const std::string& token, const std::string& room_code) {
        std::lock_guard lock(mutex_);
        if (auto it = players_.find(token); it != players_.end()) {
            it->second.room_code = room_code;
        }
    }
    void set_player_identity(const std::string& token,
                             std::optional<std::array<std::uint8_t, 32>> identity) {
        std::lock_guard lock(mutex_);
        if (auto it = players_.find(token); it != players_.end()) {
            it->second.identity = identity;
        }
    }
    std::optional<std::array<std::uint8_t, 32>> identity_of(const std::string& token) const {
        std::lock_guard lock(mutex_);
        const auto it = players_.find(token);
        return it == players_.end() ? std::nullopt : it->second.identity;
    }
    // Forgets a player whose connection ended while not seated anywhere.
    void forget_player(const std::string& token) {
        std::lock_guard lock(mutex_);
        players_.erase(token);
    }
    // --- seats restored after a restart (ServerCore::restore_matches) ---
    // A restored seat that the holder of a resume token may claim: the store knows only the
    // token's hash (token_key, any string form of it). Returns the player id the room's seat waits
    // for.
    std::int64_t add_restored_seat(const std::string& token_key, const std::string& room_code) {
        std::lock_guard lock(mutex_);
        const std::int64_t id = next_player_id_++;
        restored_[token_key] = {id, room_code};
        return id;
    }
    // The player whose token hashes to token_key claims its restored seat: a player record with
    // that token (so the seat is resumed as usual) replaces the claim. Empty if none waits.
    std::optional<PlayerRecord> claim_restored(const std::string& token,
                                               const std::string& token_key) {
        std::lock_guard lock(mutex_);
        const auto it = restored_.find(token_key);
        if (it == restored_.end() || players_.count(token) != 0) {
            return std::nullopt;
        }
        PlayerRecord record{it->second.first, token, it->second.second};
        restored_.erase(it);
        players_[token] = record;
        return record;
    }
    std::size_t player_count() const {
        std::lock_guard lock(mutex_);
        return players_.size();
    }

    // --- rooms ---
    using RoomFactory = std::function<std::shared_ptr<RoomT>(const std::string& code)>;
    // A new room with a fresh code (or `given`, a code reserved for it elsewhere, unless a room
    // here has it), or too_many_rooms.
    std::variant<std::shared_ptr<RoomT>, proto::Error> create_room(const RoomFactory& make,
                                                                   const std::string& given = {}) {
        std::lock_guard lock(mutex_);
        if (rooms_.size() >= max_rooms_) {
            return proto::Error{std::string(proto::code::kTooManyRooms),
                                "The server has no room for another room; try again later."};
        }
        std::string code = given;
        while (code.empty() || rooms_.count(code) != 0) {
            code = make_room_code(random_);
        }
        auto room = make(code);
        rooms_[code] = room;
        return room;
    }
    // A room under a given code (a room restored after a restart), or null if the code is taken.
    // Not bound by the room limit: the room existed before.
    std::shared_ptr<RoomT> add_room(const std::string& code, const RoomFactory& make) {
        std::lock_guard lock(mutex_);
        if (rooms_.count(code) != 0) {
            return nullptr;
        }
        auto room = make(code);
        rooms_[code] = room;
        return room;
    }
    std::shared_ptr<RoomT> find_room(const std::string& code) const {
        std::lock_guard lock(mutex_);
        const auto it = rooms_.find(code);
        return it == rooms_.end() ? nullptr : it->second;
    }
    // Removes the room and the records of players last seated there (a room is removed only
    // when no human holds a seat, so they are gone or elsewhere).
    void remove_room(const std::string& code) {
        std::lock_guard lock(mutex_);
        rooms_.erase(code);
        std::erase_if(players_, [&](const auto& entry) { return entry.second.room_code == code; });
        std::erase_if(restored_, [&](const auto& entry) { return entry.second.second == code; });
    }
    std::size_t room_count() const {
        std::lock_guard lock(mutex_);
        return rooms_.size();
    }
    template <class F> void for_each_room(F&& f) const {
        std::vector<std::shared_ptr<RoomT>> rooms;
        {
            std::lock_guard lock(mutex_);
            for (const auto& [code, room] : rooms_) {
                rooms.push_back(room);
            }
        }
        for (auto& room : rooms) {
            f(room);
        }
    }

    // --- quick match ---
    // Groups the waiter with the seats - 1 longest-waiting other players of the same rule set
    // and seat count: returns them, longest-waiting first, taken out of the queue. With fewer
    // waiting, queues the waiter (once: a player already queued keeps its place) and returns
    // nothing.
    std::optional<std::vector<WaiterT>> quick_match(proto::RuleSet rule_set, int seats,
                                                    std::int64_t player_id, WaiterT waiter) {
        std::lock_guard lock(mutex_);
        auto& queue = queues_[{rule_set, seats}];
        const auto others = static_cast<std::size_t>(std::count_if(
            queue.begin(), queue.end(), [&](const auto& w) { return w.first != player_id; }));
        if (seats >= 2 && others >= static_cast<std::size_t>(seats - 1)) {
            std::vector<WaiterT> group;
            for (auto it = queue.begin();
                 it != queue.end() && group.size() < static_cast<std::size_t>(seats - 1);) {
                if (it->first == player_id) {
                    ++it;
                    continue;
                }
                group.push_back(std::move(it->second));
                it = queue.erase(it);
            }
            std::erase_if(queue, [&](const auto& w) { return w.first == player_id; });
            return group;
        }
        if (std::none_of(queue.begin(), queue.end(),
                         [&](const auto& w) { return w.first == player_id; })) {
            queue.emplace_back(player_id, std::move(waiter));
        }
        return std::nullopt;
    }
    // The wait of player_id ran out: it and every other player waiting for the same rule set
    // and seat count leave the queue together (to be seated with bots); returns the others,
    // longest-waiting first. Nothing if player_id was not waiting there (a group took it).
    std::optional<std::vector<WaiterT>> take_waiting(proto::RuleSet rule_set, int seats,
                                                     std::int64_t player_id) {
        std::lock_guard lock(mutex_);
        auto& queue = queues_[{rule_set, seats}];
        if (std::none_of(queue.begin(), queue.end(),
                         [&](const auto& w) { return w.first == player_id; })) {
            return std::nullopt;
        }
        std::vector<WaiterT> others;
        for (auto& w : queue) {
            if (w.first != player_id) {
                others.push_back(std::move(w.second));
            }
        }
        queue.clear();
        return others;
    }
    // Takes the player out of every queue; true if it was waiting (so nobody paired it).
    bool cancel_quick_match(std::int64_t player_id) {
        std::lock_guard lock(mutex_);
        std::size_t removed = 0;
        for (auto& [mode, queue] : queues_) {
            removed += std::erase_if(queue, [&](const auto& w) { return w.first == player_id; });
        }
        return removed > 0;
    }
    std::size_t waiting_count() const {
        std::lock_guard lock(mutex_);
        std::size_t n = 0;
        for (const auto& [mode, queue] : queues_) {
            n += queue.size();
        }
        return n;
    }

private:
    mutable std::mutex mutex_;
    RandomSource& random_;
    std::size_t max_rooms_;
    std::int64_t next_player_id_ = 1;
    std::unordered_map<std::string, PlayerRecord> players_;
    // Restored seats not yet claimed: token key -> (player id, room code).
    std::unordered_map<std::string, std::pair<std::int64_t, std::string>> restored_;
    std::unordered_map<std::string, std::shared_ptr<RoomT>> rooms_;
    // By (rule set, seat count): (player id, waiter), longest-waiting first.
    std::map<std::pair<proto::RuleSet, int>, std::deque<std::pair<std::int64_t, WaiterT>>> queues_;
};

} // namespace carrom::server
