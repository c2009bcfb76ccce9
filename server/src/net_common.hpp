#pragma once
// Private to the network layer: Boost includes and the shared server core. Only net_*.cpp
// include this.

#include "carrom/room/clock.hpp"
#include "carrom/room/room.hpp"
#include "carrom/server/bot_factory.hpp"
#include "carrom/server/metrics.hpp"
#include "carrom/server/random.hpp"
#include "carrom/server/registry.hpp"
#include "carrom/server/settings.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace carrom::server::net {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

class WsSession;
class RoomActor;

using SessionRegistry = Registry<RoomActor, std::weak_ptr<WsSession>>;

std::chrono::milliseconds to_duration(double seconds);

// Everything the sessions and rooms share. Lives as long as the Server.
struct Core {
    Core(ServerSettings s, BotFactory b);

    // Declaration order matters for destruction: objects owned by pending handlers die with
    // ioc and may still touch clock, random and metrics; rooms in the registry own timers that
    // need ioc.
    ServerSettings settings;
    BotFactory bots;
    room::SteadyClock clock;
    SystemRandom random;
    Metrics metrics;
    asio::io_context ioc;
    SessionRegistry registry;
    asio::thread_pool bot_pool{1}; // bot thinking, never on an I/O thread
    std::atomic<bool> stopping{false};

    // Live WebSocket sessions (for shutdown).
    std::mutex sessions_mutex;
    std::unordered_map<const WsSession*, std::weak_ptr<WsSession>> sessions;
    void add_session(const std::shared_ptr<WsSession>& session);
    void remove_session(const WsSession* session);

    // A new room (counted in metrics), or an error.
    std::variant<std::shared_ptr<RoomActor>, proto::Error>
    create_room(proto::RuleSet rule_set, const proto::RoomOptions& options);
    void remove_room(const std::string& code);
};

// A room on its own strand, with the timer that drives Room::tick.
class RoomActor : public std::enable_shared_from_this<RoomActor> {
public:
    RoomActor(Core& core, std::string code, room::RoomConfig config);
    ~RoomActor();

    const std::string& code() const { return code_; }
    // Runs f(room) on the room's strand, then reschedules the timer and handles bots and an
    // abandoned room.
    template <class F> void post(F&& f) {
        asio::post(strand_, [self = shared_from_this(), f = std::forward<F>(f)]() mutable {
            f(self->room_);
            self->after();
        });
    }
    void stop(); // cancel the timer (shutdown)

private:
    void after();
    void schedule(std::int64_t wake_ms);
    void on_timer();

    Core& core_;
    std::string code_;
    asio::strand<asio::io_context::executor_type> strand_;
    asio::steady_timer timer_;
    room::Room room_;
    std::int64_t scheduled_ms_ = -1;
    bool removed_ = false;
};

// Plain HTTP or the WebSocket upgrade: reads one request, then answers it or hands the stream
// to a WsSession.
void start_http_session(Core& core, tcp::socket socket);

// Hands an upgrade request to a new WebSocket session.
void start_ws_session(Core& core, beast::tcp_stream stream,
                      http::request<http::string_body> request);

} // namespace carrom::server::net
