#include "server_core.hpp"

#include "room_actor.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

namespace carrom::server {

ServerCore::ServerCore(ServerSettings s, BotFactory b, std::shared_ptr<const StaticSite> w,
                       std::shared_ptr<store::MatchStore> st)
    : settings(std::move(s)), bots(std::move(b)), web(std::move(w)), store(std::move(st)),
      ioc(std::max(1, settings.threads)),
      registry(random, static_cast<std::size_t>(std::max(0, settings.max_rooms))) {}

void ServerCore::add_session(const std::shared_ptr<WsSession>& session) {
    std::lock_guard lock(sessions_mutex);
    sessions[session.get()] = session;
}

void ServerCore::remove_session(const WsSession* session) {
    std::lock_guard lock(sessions_mutex);
    sessions.erase(session);
}

bool ServerCore::add_address(const std::string& address) {
    std::lock_guard lock(addresses_mutex);
    int& open = connections_by_address[address];
    if (open >= settings.max_connections_per_address) {
        if (open == 0) {
            connections_by_address.erase(address);
        }
        return false;
    }
    ++open;
    return true;
}

void ServerCore::remove_address(const std::string& address) {
    std::lock_guard lock(addresses_mutex);
    auto it = connections_by_address.find(address);
    if (it != connections_by_address.end() && --it->second <= 0) {
        connections_by_address.erase(it);
    }
}

std::variant<std::shared_ptr<RoomActor>, proto::Error>
ServerCore::create_room(proto::RuleSet rule_set, const proto::RoomOptions& options) {
    room::RoomConfig config;
    config.rule_set = rule_set;
    config.rules = room::make_rules_config(rule_set, options, settings.shot_clock_s);
    config.snapshot_hz = settings.snapshot_hz;
    config.time_scale = settings.time_scale;
    config.grace_s = settings.grace_s;
    config.server_version = CARROM_SERVER_VERSION;
    auto created = registry.create_room(
        [&](const std::string& code) { return std::make_shared<RoomActor>(*this, code, config); });
    if (const auto* room = std::get_if<std::shared_ptr<RoomActor>>(&created)) {
        (*room)->bind_journal();
        metrics.rooms.fetch_add(1, std::memory_order_relaxed);
        spdlog::info("room {} created ({})", (*room)->code(), proto::to_string(rule_set));
    }
    return created;
}

void ServerCore::remove_room(const std::string& code) {
    registry.remove_room(code);
    metrics.rooms.fetch_sub(1, std::memory_order_relaxed);
    spdlog::info("room {} closed", code);
}

} // namespace carrom::server
