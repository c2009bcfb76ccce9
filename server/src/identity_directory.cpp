#include "identity_directory.hpp"

#include "player_name_key.hpp"

namespace carrom::server {

namespace {

proto::Error name_taken_error(const std::string& name) {
    return proto::Error{std::string(proto::code::kNameTaken),
                        "The name " + name + " belongs to another player; choose another name."};
}

} // namespace

IdentityDirectory::IdentityDirectory()
    : new_identities_(kNewIdentitiesPerMinute / 60.0, kNewIdentitiesPerMinute,
                      kNewIdentityAddresses) {}

void IdentityDirectory::load(const std::vector<store::IdentifiedPlayer>& players) {
    const std::lock_guard lock(mutex_);
    by_key_.clear();
    key_by_name_.clear();
    for (const store::IdentifiedPlayer& player : players) {
        const std::string key = store::to_hex(player.key_hash);
        by_key_[key] = player;
        key_by_name_[player.name_key] = key;
    }
}

std::variant<IdentityDirectory::Claimed, proto::Error>
IdentityDirectory::claim(const store::PlayerKeyHash& key_hash, const std::string& name,
                         const std::string& address, std::int64_t now_ms,
                         std::int64_t monotonic_ms) {
    const std::optional<std::string> name_key = player_name_key(name);
    if (!name_key) {
        return proto::Error{std::string(proto::code::kBadField),
                            "name: must have a character other than spaces and invisible ones."};
    }
    const std::string key = store::to_hex(key_hash);
    const std::lock_guard lock(mutex_);
    if (const auto holder = key_by_name_.find(*name_key);
        holder != key_by_name_.end() && holder->second != key) {
        return name_taken_error(name);
    }
    auto it = by_key_.find(key);
    if (it == by_key_.end()) {
        if (new_identities_.take(address, monotonic_ms) != 0) {
            return proto::Error{std::string(proto::code::kTooManyIdentities),
                                "Too many new players from your address; try again in a minute."};
        }
        store::IdentifiedPlayer player{key_hash, name, *name_key, now_ms};
        by_key_[key] = player;
        key_by_name_[*name_key] = key;
        return Claimed{player, true};
    }
    store::IdentifiedPlayer& player = it->second;
    if (player.name == name) {
        return Claimed{player, false};
    }
    key_by_name_.erase(player.name_key);
    player.name = name;
    player.name_key = *name_key;
    key_by_name_[*name_key] = key;
    return Claimed{player, true};
}

std::optional<proto::Error> IdentityDirectory::check_guest_name(const std::string& name) const {
    const std::optional<std::string> name_key = player_name_key(name);
    const std::lock_guard lock(mutex_);
    if (name_key && key_by_name_.count(*name_key) != 0) {
        return name_taken_error(name);
    }
    return std::nullopt;
}

std::optional<store::IdentifiedPlayer>
IdentityDirectory::find(const store::PlayerKeyHash& key_hash) const {
    const std::lock_guard lock(mutex_);
    const auto it = by_key_.find(store::to_hex(key_hash));
    if (it == by_key_.end()) {
        return std::nullopt;
    }
    return it->second;
}

std::size_t IdentityDirectory::size() const {
    const std::lock_guard lock(mutex_);
    return by_key_.size();
}

} // namespace carrom::server
