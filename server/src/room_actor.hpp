#pragma once
// Private to server/src: a room on its own strand, with the timer that drives Room::tick and the
// hand-off of bot turns to the bot worker. The room's state is touched only on the strand.

#include "asio_types.hpp"
#include "room_logger.hpp"
#include "store/cluster.hpp"
#include "store_journal.hpp"

#include "carrom/room/room.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace carrom::server {

struct ServerCore;

class RoomActor : public std::enable_shared_from_this<RoomActor> {
public:
    RoomActor(ServerCore& core, std::string code, room::RoomConfig config);
    ~RoomActor();

    const std::string& code() const { return code_; }
    // Runs f(room) on the room's strand, then reschedules the timer and handles bots and an
    // abandoned room.
    // Nothing runs once the match is lost (lose()).
    template <class F> void post(F&& f) {
        asio::post(strand_, [self = shared_from_this(), f = std::forward<F>(f)]() mutable {
            if (self->lost_) {
                return;
            }
            f(self->room_);
            self->after();
        });
    }
    void stop(); // cancel the timer (shutdown)
    // Restores an unfinished match into the new room (Room::restore), before the I/O threads
    // run; on success the room's timers and bot turns start on its strand. Why not, otherwise.
    std::optional<std::string> restore(const proto::MatchJournal& journal,
                                       std::vector<room::RestoredSeat> seats);
    // A takeover while the server runs (docs/cluster.md): the same restore on the room's strand,
    // queued before anything a client can send it (call it before the room is in the registry,
    // or from its factory). Refused: logged, the room removed. on_done(true) once it runs.
    void restore_on_strand(proto::MatchJournal journal, std::vector<room::RestoredSeat> seats,
                           std::function<void(bool restored)> on_done);
    // The match is another instance's (cluster mode): from now on the room takes nothing (no
    // message, no stroke confirmation, no bot shot, no timer), closes its members' connections
    // with close code 4004 match_moved and leaves the registry. Any thread.
    void lose();
    // A draining instance hands the match to another (docs/cluster.md, "Draining"): from now on
    // the room takes nothing, as after lose(), but keeps its connections (the server tells
    // them where to go). The future is ready once the room is frozen on its strand: with the
    // room's description when it waits for its players (Room::waiting_for_players), for the
    // new instance to open it again.
    std::future<std::optional<store::WaitingRoom>> freeze();
    // Ready once everything queued on the room's strand before it has run (Server::shutdown:
    // what the rooms send their members is on its way before the members are told to go).
    std::future<void> settled();
    // A room opened with nobody in it (handed over while it waited for its players): removed
    // after `wait` unless somebody is in it then. Any thread.
    void remove_if_nobody_came(std::chrono::milliseconds wait);
    // With a match store: the journal's write confirmations go to the room on its strand. Called
    // once, right after construction (it needs the actor's shared_ptr).
    void bind_journal();

    // A rated room (docs/ratings.md): marked once, before anyone takes a seat. Its games are
    // rated when two different identified players hold the seats as the game starts.
    void set_rated() { rated_.store(true); }
    bool rated() const { return rated_.load(); }
    // An identified player takes a seat of this rated room: false (same_player) when the same
    // identity already took the other one. Any thread.
    bool admit_identity(const store::PlayerKeyHash& key_hash);

private:
    void after();
    void schedule(std::int64_t wake_ms);
    void on_timer();

    ServerCore& core_;
    std::string code_;
    std::atomic<bool> rated_{false}; // before journal_, which reads it
    std::mutex identities_mutex_;
    std::vector<store::PlayerKeyHash> identities_; // rated room: the identities seated so far
    asio::strand<asio::io_context::executor_type> strand_;
    asio::steady_timer timer_;
    RoomLogger logger_;                     // before room_, which reports to it
    std::unique_ptr<StoreJournal> journal_; // null without a store; before room_ too
    room::Room room_;
    std::int64_t scheduled_ms_ = -1;
    bool removed_ = false;
    bool lost_ = false; // strand only
};

} // namespace carrom::server
