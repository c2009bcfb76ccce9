#pragma once
// Private to server/src: what the listener, the sessions and the room actors share. Lives as long
// as the Server.

#include "address_rate_limiter.hpp"
#include "asio_types.hpp"
#include "confirmation_gate.hpp"
#include "identity_directory.hpp"
#include "match_api_reader.hpp"
#include "rated_queue.hpp"

#include "carrom/proto/client_messages.hpp"
#include "carrom/room/clock.hpp"
#include "carrom/room/room.hpp"
#include "carrom/server/bot_factory.hpp"
#include "carrom/server/metrics.hpp"
#include "carrom/server/random.hpp"
#include "carrom/server/registry.hpp"
#include "carrom/server/settings.hpp"
#include "carrom/server/static_site.hpp"
#include "store/cluster.hpp"
#include "store/match_store.hpp"

#include <boost/asio/thread_pool.hpp>

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <variant>

namespace carrom::server {

class RoomActor;
class TlsContext;
class WsSession;

using SessionRegistry = Registry<RoomActor, std::weak_ptr<WsSession>>;

struct ServerCore {
    ServerCore(ServerSettings s, BotFactory b, std::shared_ptr<const StaticSite> w,
               std::shared_ptr<store::MatchStore> st);

    // Declaration order matters for destruction: objects owned by pending handlers die with
    // ioc and may still touch clock, random and metrics; rooms in the registry own timers that
    // need ioc.
    ServerSettings settings;
    BotFactory bots;
    std::shared_ptr<const StaticSite> web; // the web client's files; null = none
    // Where match journals go; null = none (--data none). May outlive the server (main keeps a
    // reference); its confirmations pass through `confirmations`.
    std::shared_ptr<store::MatchStore> store;
    // Write confirmations reach the rooms through it; closed by Server::shutdown once the I/O
    // threads have ended (confirmation_gate.hpp). Shared with the callbacks the store holds.
    std::shared_ptr<ConfirmationGate> confirmations = std::make_shared<ConfirmationGate>();
    room::SteadyClock clock;
    SystemRandom random;
    Metrics metrics;
    asio::io_context ioc;
    SessionRegistry registry;
    asio::thread_pool bot_pool{1}; // bot thinking, never on an I/O thread
    std::atomic<bool> stopping{false};
    // Answers the match API off the I/O threads; null without a store. Declared after ioc, so
    // it is stopped (Server::shutdown) and destroyed before ioc: its answers post to sessions.
    std::unique_ptr<MatchApiReader> match_reader;
    AddressRateLimiter http_limiter;
    // Identified players (their names) and the rated quick-match queue (docs/ratings.md).
    IdentityDirectory identities;
    RatedQueue rated_queue;
    // The TLS certificate and key; null = plain connections only (Server::listen loads it).
    std::shared_ptr<TlsContext> tls;

    // Live WebSocket sessions (for shutdown).
    std::mutex sessions_mutex;
    std::unordered_map<const WsSession*, std::weak_ptr<WsSession>> sessions;
    void add_session(const std::shared_ptr<WsSession>& session);
    void remove_session(const WsSession* session);

    // Open WebSocket connections per client address (settings.max_connections_per_address).
    std::mutex addresses_mutex;
    std::unordered_map<std::string, int> connections_by_address;
    // Counts one more connection from address; false (nothing counted) when it has the maximum.
    bool add_address(const std::string& address);
    void remove_address(const std::string& address);

    // A new room of `seats` seats (2 or 4; counted in metrics, logged), or an error. A rated
    // room (docs/ratings.md) has no aim assist. In cluster mode its code is one the cluster
    // reserved for this instance (`code`, when given: one reserved already), or
    // store_unavailable when none is (the database does not answer).
    std::variant<std::shared_ptr<RoomActor>, proto::Error>
    create_room(proto::RuleSet rule_set, const proto::RoomOptions& options, int seats = 2,
                bool server_bots = false, bool rated = false, std::string code = {});
    void remove_room(const std::string& code);
    // store_unavailable while the match store does not answer (its writes failing; cluster
    // mode: the lease not renewed either): no new room, quick match or rematch then
    // (docs/cluster.md, "The database down"). None without a store.
    std::optional<proto::Error> store_refusal() const;
    // The store_unavailable error of store_refusal (also: no room code reserved in cluster mode).
    static proto::Error store_unavailable();

    // Cluster mode (docs/cluster.md): the store's cluster, or null.
    store::Cluster* cluster() const { return store ? store->cluster() : nullptr; }
    // Quick-match tickets of this instance's waiting sessions, by ticket.
    std::mutex tickets_mutex;
    std::unordered_map<std::int64_t, std::weak_ptr<WsSession>> tickets;
    // Another instance paired these tickets (on the directory's thread): their sessions move.
    void quick_paired(std::vector<store::QuickPairing> pairings);
    // Rooms waiting for their players that a draining instance handed to this one (on the
    // cluster's thread): each opened under its code, empty until its members come back, and
    // closed if nobody has after the grace period (--grace, at least 1 s).
    void open_handed_rooms(std::vector<store::WaitingRoom> rooms);
    // A room's actor under code, rated or not, its journal bound (for registry.add_room).
    std::shared_ptr<RoomActor> new_room_actor(const std::string& code,
                                              const room::RoomConfig& config, bool rated);
    // A room's config from its rule set and rules, with this server's settings.
    room::RoomConfig room_config(proto::RuleSet rule_set, const rules::RulesConfig& rules,
                                 bool rated) const;

    // At start, before the I/O threads run: every unfinished match in the store whose journal
    // replays with this build is restored in a room under its old code (docs/store.md,
    // "Recovery after a restart"); the others are logged and left in the store. Returns how many.
    int restore_matches();
    // Cluster mode (docs/cluster.md), on the cluster's thread: matches this instance claimed
    // from a dead instance, each restored as at a restart in a room under its code, restored on
    // the room's strand.
    void take_over(std::vector<store::RecoveredMatch> matches);
    // Cluster mode: another instance took this match over; its room stops (RoomActor::lose).
    void match_lost(const std::string& match_id, const std::string& room_code);
    // One match of restore_matches (running: false) or take_over (true); false when refused
    // (logged).
    bool restore_match(const store::RecoveredMatch& match, bool running);
    // A resume token the registry does not know: the player of a restored seat whose token hash
    // the store kept, given a player record with that same token. Empty if none.
    std::optional<PlayerRecord> claim_restored_seat(const std::string& token);
    // At start: the identified players of the store into `identities` (logged on failure: the
    // server then knows no identity and every hello with a key creates one).
    void load_identities();
};

} // namespace carrom::server
