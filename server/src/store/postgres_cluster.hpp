#pragma once
// Cluster mode on PostgreSQL (docs/cluster.md): this instance's row in `instances` and its lease,
// the takeover of orphaned matches, and the check that the matches it owns are still its own.
//
// Threads: open() and claim() run on the caller's thread (the server's start, before its I/O
// threads run); after start(), only the cluster thread uses the connection: every renew_interval
// it renews the lease (expiry = the database's now() + lease), checks ownership, and claims
// orphaned matches. status() is safe on any thread.
//
// The lease connection holds a session advisory lock on the instance id (kInstanceLockClass) for
// as long as it lives: a second live process with the same id is refused
// (cluster_instance_in_use, after 3 s of tries); one started after the holder died (even by
// kill -9) gets it.

#include <pqxx/connection>
#include <pqxx/notification>
#include <pqxx/transaction_base>

#include "store/cluster.hpp"
#include "store/match_ownership.hpp"
#include "store/postgres_directory.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace carrom::store::postgres {

struct ClusterOptions {
    std::string instance_id;
    std::string public_url;
    std::chrono::milliseconds lease{10000}; // a lease lasts this long after each renewal
    // Matches claimed in one takeover scan, at most.
    int claim_limit = 200;
};

// The options' checks, for the operator: bad_instance_id (1 to 64 characters of
// [A-Za-z0-9._-]), bad_public_url (ws:// or wss:// and a host, at most 2,000 characters, no
// space, quote, backslash or control character), bad_lease (0.5 s to 10 min).
std::optional<StoreError> check_cluster_options(const ClusterOptions& options);
// A new instance id: the host name (its [A-Za-z0-9.-] characters, at most 40), a dash and 6
// random characters of [0-9a-z].
std::string generate_instance_id();

class PostgresCluster final : public Cluster {
public:
    PostgresCluster(std::string url, std::string shown, ClusterOptions options,
                    std::shared_ptr<MatchOwnership> ownership);
    ~PostgresCluster() override;
    PostgresCluster(const PostgresCluster&) = delete;
    PostgresCluster& operator=(const PostgresCluster&) = delete;

    // Connects, takes the instance lock and registers the instance with a fresh lease. An error
    // for the operator (cluster_instance_in_use, or the store's connection errors).
    std::optional<StoreError> open();
    // Claims the unfinished matches no live instance owns (their owner's lease expired, or no
    // owner) in one conditional UPDATE that increments their owner_epoch, so each is claimed by
    // one instance only, and returns them with their journals (as one transaction). With
    // mine_too (the start): this instance id's own matches too (a process of the same id that
    // died). The claimed matches join the ownership.
    Loaded<std::vector<RecoveredMatch>> claim(bool mine_too);
    // Ends the lease now (expiry = now()): the other instances claim what is left at their next
    // scan. Call once the store's writes are flushed.
    void end_lease();

    void start(ClusterHandlers handlers) override;
    void stop() override;
    ClusterStatus status() const override;

    std::optional<std::string> take_room_code() override { return directory_.take_room_code(); }
    void release_room_code(const std::string& code) override { directory_.release_room_code(code); }
    void locate_room(std::string code, Answer<RoomLocation> done) override {
        directory_.locate_room(std::move(code), std::move(done));
    }
    void locate_seat(TokenHash token, Answer<RoomLocation> done) override {
        directory_.locate_seat(token, std::move(done));
    }
    void quick_enqueue(QuickRequest request, Answer<QuickEnqueued> done) override {
        directory_.quick_enqueue(std::move(request), std::move(done));
    }
    void quick_withdraw(std::int64_t ticket, Answer<bool> done) override {
        directory_.quick_withdraw(ticket, std::move(done));
    }
    Loaded<std::vector<HandedMatch>> hand_over(std::vector<WaitingRoom> waiting) override;

    std::chrono::milliseconds renew_interval() const { return options_.lease / 3; }

private:
    void run();
    // One round of the cluster thread: renew, check, claim. Logs its failures.
    void round();
    // True when the lease had expired (or the row was gone) before this renewal.
    bool renew();
    // The instance's row with lease_expires = now() + lease (registering: its public URL and
    // start time too), in t; lease_expires_ms_ from it.
    void write_lease(pqxx::transaction_base& t, bool registering);
    void check_owned();
    // The rooms waiting for their players that a draining instance handed to this one, taken
    // (rooms.waiting set back to NULL) and given to on_rooms_handed.
    void take_handed_rooms();
    // Waits up to renew_interval for stop() or a NOTIFY on kWakeChannel (an instance handed
    // matches over): the next round comes at once.
    void wait_for_next_round();
    pqxx::connection& connection(); // made again (and the instance lock retaken) after it broke
    void drop_connection();

    std::string url_;
    std::string shown_;
    ClusterOptions options_;
    PostgresDirectory directory_;
    std::shared_ptr<MatchOwnership> ownership_;
    std::unique_ptr<pqxx::connection> connection_;
    // LISTENs on kWakeChannel on connection_ (made with it, dropped before it).
    std::unique_ptr<pqxx::notification_receiver> wake_receiver_;
    bool woken_ = false; // cluster thread: a NOTIFY arrived
    ClusterHandlers handlers_;

    std::atomic<bool> lease_ok_{false};
    std::atomic<std::int64_t> lease_expires_ms_{0};
    std::atomic<std::uint64_t> takeovers_total_{0};
    bool registered_ = false; // open() succeeded
    bool failing_ = false;
    // Cluster thread: no claim before this (steady clock), after this instance's lease lapsed or
    // a round failed.
    std::chrono::steady_clock::time_point
        claims_from_{}; // cluster thread: the last round failed (one log line per outage)

    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    std::thread thread_;
};

} // namespace carrom::store::postgres
