#include "server_core.hpp"

#include "bot_seat_name.hpp"

#include "room_actor.hpp"
#include "waiting_room.hpp"
#include "ws_session.hpp"

#include "store/cluster.hpp"

#include "carrom/proto/journal_replay.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <string_view>

namespace carrom::server {

ServerCore::ServerCore(ServerSettings s, BotFactory b, std::shared_ptr<const StaticSite> w,
                       std::shared_ptr<store::MatchStore> st)
    : settings(std::move(s)), bots(std::move(b)), web(std::move(w)), store(std::move(st)),
      ioc(std::max(1, settings.threads)),
      registry(random, static_cast<std::size_t>(std::max(0, settings.max_rooms))),
      match_reader(store ? std::make_unique<MatchApiReader>(store, kMatchApiMaxPending) : nullptr),
      http_limiter(settings.http_rate, settings.http_burst, settings.http_rate_addresses) {}

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

proto::Error ServerCore::store_unavailable() {
    return proto::Error{std::string(proto::code::kStoreUnavailable),
                        "The server cannot start a match now because its database does not "
                        "answer; try again in a moment."};
}

std::optional<proto::Error> ServerCore::store_refusal() const {
    if (!store) {
        return std::nullopt;
    }
    const store::Cluster* in_cluster = cluster();
    if (!store->health().degraded && (in_cluster == nullptr || in_cluster->status().lease_ok)) {
        return std::nullopt;
    }
    return store_unavailable();
}

std::variant<std::shared_ptr<RoomActor>, proto::Error>
ServerCore::create_room(proto::RuleSet rule_set, const proto::RoomOptions& options, int seats,
                        bool server_bots, bool rated, std::string code) {
    if (auto refusal = store_refusal()) {
        return *std::move(refusal);
    }
    if (store::Cluster* in_cluster = cluster(); in_cluster != nullptr && code.empty()) {
        auto reserved = in_cluster->take_room_code();
        if (!reserved) { // none reserved: the database has not answered for a while
            return store_unavailable();
        }
        code = std::move(*reserved);
    }
    // A game against the server's bots gives its players the longer of the two default clocks;
    // --shot-clock 0 turns every default clock off.
    const double default_clock_s = server_bots && settings.shot_clock_s > 0.0
                                       ? std::max(settings.shot_clock_s, settings.bot_shot_clock_s)
                                       : settings.shot_clock_s;
    rules::RulesConfig rules = room::make_rules_config(rule_set, options, default_clock_s);
    rules.seat_count = seats;
    const room::RoomConfig config = room_config(rule_set, rules, rated);
    auto created = registry.create_room(
        [&](const std::string& c) { return std::make_shared<RoomActor>(*this, c, config); }, code);
    if (std::holds_alternative<proto::Error>(created) && !code.empty()) {
        cluster()->release_room_code(code); // too many rooms here
    }
    if (const auto* room = std::get_if<std::shared_ptr<RoomActor>>(&created)) {
        if (rated) {
            (*room)->set_rated(); // before bind_journal: the journal reads it
        }
        (*room)->bind_journal();
        metrics.rooms.fetch_add(1, std::memory_order_relaxed);
        spdlog::info("room {} created ({}, {} seats)", (*room)->code(), proto::to_string(rule_set),
                     seats);
    }
    return created;
}

void ServerCore::quick_paired(std::vector<store::QuickPairing> pairings) {
    for (store::QuickPairing& pairing : pairings) {
        std::shared_ptr<WsSession> session;
        {
            const std::lock_guard lock(tickets_mutex);
            const auto it = tickets.find(pairing.ticket);
            if (it != tickets.end()) {
                session = it->second.lock();
                tickets.erase(it);
            }
        }
        if (session) {
            session->on_quick_paired(std::move(pairing));
        } // else the player left: the other instance's room gives the seat to a bot
    }
}

void ServerCore::load_identities() {
    auto loaded = store->load_players();
    if (!loaded.ok()) {
        spdlog::error("store: cannot read the identified players: {}", loaded.error->message);
        return;
    }
    identities.load(loaded.value);
    spdlog::info("{} identified players", loaded.value.size());
}

room::RoomConfig ServerCore::room_config(proto::RuleSet rule_set, const rules::RulesConfig& rules,
                                         bool rated) const {
    room::RoomConfig config;
    config.rule_set = rule_set;
    config.rules = rules;
    config.snapshot_hz = settings.snapshot_hz;
    config.contact_snapshots = settings.contact_snapshots;
    config.time_scale = settings.time_scale;
    config.grace_s = settings.grace_s;
    config.server_version = CARROM_SERVER_VERSION;
    config.aim_assist = !rated;
    return config;
}

std::shared_ptr<RoomActor> ServerCore::new_room_actor(const std::string& code,
                                                      const room::RoomConfig& config, bool rated) {
    auto made = std::make_shared<RoomActor>(*this, code, config);
    if (rated) {
        made->set_rated(); // before bind_journal: the journal reads it
    }
    made->bind_journal();
    return made;
}

void ServerCore::open_handed_rooms(std::vector<store::WaitingRoom> rooms) {
    for (const store::WaitingRoom& handed : rooms) {
        const auto read = read_waiting_room(handed.description);
        if (const auto* error = std::get_if<proto::Error>(&read)) {
            spdlog::warn("room {} handed over but not opened ({}: {})", handed.code, error->code,
                         error->message);
            if (store::Cluster* in_cluster = cluster()) {
                in_cluster->release_room_code(handed.code);
            }
            continue;
        }
        const WaitingRoomSpec& spec = std::get<WaitingRoomSpec>(read);
        const room::RoomConfig config = room_config(spec.rule_set, spec.rules, spec.rated);
        auto actor = registry.add_room(handed.code, [&](const std::string& c) {
            return new_room_actor(c, config, spec.rated);
        });
        if (!actor) {
            spdlog::warn("room {} handed over but not opened: the code is taken here", handed.code);
            continue;
        }
        metrics.rooms.fetch_add(1, std::memory_order_relaxed);
        spdlog::info("room {} handed over: waiting for its players ({}, {} seats)", handed.code,
                     proto::to_string(spec.rule_set), spec.rules.seat_count);
        // Its members are on their way (redirect "moved"); a room nobody came to closes.
        actor->remove_if_nobody_came(to_duration(std::max(settings.grace_s, 1.0)));
    }
}

void ServerCore::remove_room(const std::string& code) {
    registry.remove_room(code);
    if (store::Cluster* in_cluster = cluster(); in_cluster != nullptr && !stopping.load()) {
        // Free for the cluster again; a room stopped at shutdown keeps its code with its match.
        in_cluster->release_room_code(code);
    }
    metrics.rooms.fetch_sub(1, std::memory_order_relaxed);
    spdlog::info("room {} closed", code);
}

namespace {

std::optional<proto::RuleSet> wire_rule_set(rules::RuleSet rule_set) {
    for (const proto::RuleSet r : {proto::RuleSet::Icf, proto::RuleSet::Seed,
                                   proto::RuleSet::Freestyle, proto::RuleSet::DiscPool}) {
        if (proto::to_rules(r) == rule_set) {
            return r;
        }
    }
    return std::nullopt;
}

} // namespace

int ServerCore::restore_matches() {
    if (!store) {
        return 0;
    }
    auto loaded = store->load_unfinished();
    if (!loaded.ok()) {
        spdlog::error("match store: unfinished matches not loaded, none recovered: {}",
                      loaded.error->message);
        return 0;
    }
    int recovered = 0;
    for (const store::RecoveredMatch& match : loaded.value) {
        recovered += restore_match(match, false) ? 1 : 0;
    }
    return recovered;
}

void ServerCore::take_over(std::vector<store::RecoveredMatch> matches) {
    for (const store::RecoveredMatch& match : matches) {
        restore_match(match, true);
    }
}

void ServerCore::match_lost(const std::string& match_id, const std::string& room_code) {
    if (auto room = registry.find_room(room_code)) {
        spdlog::warn("room {}: match {} is run by another instance now; its connections here "
                     "close (4004 match_moved)",
                     room_code, match_id);
        room->lose();
    }
}

bool ServerCore::restore_match(const store::RecoveredMatch& match, bool running) {
    auto refuse = [&](std::string_view why) {
        spdlog::warn("match {} not {} (left in the store): {}", match.id,
                     running ? "taken over" : "recovered", why);
        return false;
    };
    if (match.error || !match.journal) {
        return refuse(match.error ? match.error->message : "no journal");
    }
    const proto::MatchJournal& journal = *match.journal;
    if (auto version = proto::check_versions(journal.created)) {
        return refuse(version->message);
    }
    const auto rule_set = wire_rule_set(journal.created.rule_set);
    if (!rule_set) {
        return refuse("its rule set is unknown to this server");
    }
    const auto journal_seats = room::journal_seats(journal);
    std::vector<room::RestoredSeat> seats(journal_seats.size());
    for (std::size_t i = 0; i < journal_seats.size(); ++i) {
        if (journal_seats[i].bot) {
            if (!bots) {
                return refuse("it has a bot seat and this server has no bots");
            }
            seats[i].bot = bots(bot_level_of_name(journal_seats[i].name));
        }
    }
    room::RoomConfig config = room_config(*rule_set, journal.created.rules, match.rated);
    config.physics = journal.created.physics;
    const std::string& code = journal.created.room_code;
    if (registry.find_room(code)) {
        return refuse("room code " + code + " is taken by another room here");
    }
    // Claims for the human seats, by token hash; the room waits for those player ids.
    for (std::size_t i = 0; i < seats.size(); ++i) {
        const auto& token =
            i < match.seat_tokens.size() ? match.seat_tokens[i] : std::optional<store::TokenHash>{};
        if (!seats[i].bot && token) {
            seats[i].player_id = registry.add_restored_seat(store::to_hex(*token), code);
        }
    }
    auto actor = registry.add_room(code, [&](const std::string& c) {
        auto made = new_room_actor(c, config, match.rated);
        if (running) { // queued on its strand before anything a client can send it
            made->restore_on_strand(journal, seats, [this, id = match.id, c](bool restored) {
                if (restored) {
                    metrics.rooms.fetch_add(1, std::memory_order_relaxed);
                    spdlog::info("room {} taken over: match {}", c, id);
                }
            });
        }
        return made;
    });
    if (!actor) {
        return refuse("room code " + code + " is taken by another room here");
    }
    if (running) {
        return true;
    }
    if (auto refused = actor->restore(journal, std::move(seats))) {
        actor->stop();
        registry.remove_room(code); // and the claims for its seats
        return refuse(*refused);
    }
    metrics.rooms.fetch_add(1, std::memory_order_relaxed);
    spdlog::info("room {} recovered: match {}, {} journal entries", code, match.id,
                 journal.entries.size());
    return true;
}

std::optional<PlayerRecord> ServerCore::claim_restored_seat(const std::string& token) {
    return registry.claim_restored(token, store::to_hex(store::hash_token(token)));
}

} // namespace carrom::server
