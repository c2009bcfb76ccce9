#pragma once
// Cluster mode on PostgreSQL (docs/cluster.md, "Rooms across the cluster"): the cluster's rooms
// and quick-match tickets, as one instance sees them. The table `rooms` maps every room code in
// use to the instance that runs its room: a code is reserved there (INSERT, primary key) before
// a room gets it, so codes are unique across the cluster. `quick_tickets` holds the players who
// wait for a quick match on one instance, for another instance to pair.
//
// Threads: one thread of its own with its own connection runs every request in the order asked
// and answers through the request's callback; every 200 ms it also refills the pool of reserved
// codes and, while this instance has tickets waiting, fetches the ones another instance paired
// (ClusterHandlers::on_paired); every 5 s it frees the codes and tickets of instances whose lease
// expired (a code stays while an unfinished match has it: its takeover moves it). take_room_code
// and the requests never block; hand_over blocks its caller.

#include <pqxx/connection>

#include "store/cluster.hpp"

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace carrom::store::postgres {

class PostgresDirectory {
public:
    PostgresDirectory(std::string url, std::string shown, std::string instance_id,
                      std::string public_url);
    ~PostgresDirectory();
    PostgresDirectory(const PostgresDirectory&) = delete;
    PostgresDirectory& operator=(const PostgresDirectory&) = delete;

    // At the instance's start, before start(): frees this instance id's codes that no unfinished
    // match holds (a process of the same id that died) and its old tickets, and fills the pool.
    void open();
    void start(std::function<void(std::vector<QuickPairing>)> on_paired);
    void stop(); // idempotent; requests not yet run are answered with an error

    std::optional<std::string> take_room_code();
    void release_room_code(const std::string& code);
    void locate_room(std::string code, Answer<RoomLocation> done);
    void locate_seat(TokenHash token, Answer<RoomLocation> done);
    void quick_enqueue(QuickRequest request, Answer<QuickEnqueued> done);
    void quick_withdraw(std::int64_t ticket, Answer<bool> done);

private:
    using Job = std::function<void(pqxx::connection*, const std::optional<StoreError>&)>;
    void post(Job job);
    // A request whose answer fill makes on the thread's connection; done gets it, or the error.
    template <class T> void ask(Answer<T> done, std::function<void(pqxx::connection&, T&)> fill);
    void run();
    void maintain(); // pool refill, pairings, cleanup: on the thread, between jobs
    void refill_pool(pqxx::connection& c);
    void fetch_pairings(pqxx::connection& c);
    void clean_up(pqxx::connection& c);
    pqxx::connection& connection(); // made again after it broke
    std::string random_code();

    std::string url_;
    std::string shown_;
    std::string instance_id_;
    std::string public_url_;
    std::unique_ptr<pqxx::connection> connection_; // the thread's (open(): the caller's)
    std::function<void(std::vector<QuickPairing>)> on_paired_;
    std::mt19937_64 random_; // the thread's (open(): the caller's)
    std::chrono::steady_clock::time_point next_clean_up_{};

    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Job> jobs_;
    std::vector<std::string> pool_;   // reserved codes, not yet taken
    std::size_t tickets_waiting_ = 0; // this instance's tickets not yet paired or withdrawn
    bool refill_wanted_ = false;      // the pool ran low: maintain() before the next job
    bool stopping_ = false;
    std::thread thread_;
};

} // namespace carrom::store::postgres
