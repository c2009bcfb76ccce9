#include "ws_session.hpp"

#include "client_address.hpp"

#include "room_actor.hpp"
#include "server_core.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/proto/limits.hpp"
#include "carrom/proto/version.hpp"

#include <boost/asio/post.hpp>
#include <boost/beast/core/buffers_to_string.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>

namespace carrom::server {

namespace websocket = beast::websocket;

namespace {

// Frames above this are refused by Beast itself (close 1009 without an error message); frames
// between max_message_bytes and this get a "too_large" error first.
std::size_t hard_frame_limit(std::size_t max_message_bytes) {
    return std::max<std::size_t>(max_message_bytes * 4, 65536);
}

// A client too slow for its write queue gets this long for the write in flight and the close
// frame 4003 before its socket is closed.
constexpr std::chrono::milliseconds kSlowKillAfter{1000};

} // namespace

// --- WsSession --------------------------------------------------------------------------------

WsSession::WsSession(ServerCore& core, ServerStream stream)
    : core_(core), ws_(std::move(stream)), hello_timer_(ws_.get_executor()),
      idle_timer_(ws_.get_executor()), kill_timer_(ws_.get_executor()),
      quick_timer_(ws_.get_executor()), rated_timer_(ws_.get_executor()),
      queue_(core.settings.max_queue_bytes, core.settings.snapshot_backlog),
      limiter_(core.settings.max_rate, core.settings.rate_burst, core.clock.now_ms()),
      partner_timer_(ws_.get_executor()) {}

WsSession::~WsSession() = default;

void WsSession::run(http::request<http::string_body> request) {
    forwarded_for_ = std::string(request["X-Forwarded-For"]);
    route_asked_ = std::string(request["X-Carrom-Route"]).substr(0, 64);
    websocket::stream_base::timeout timeout{};
    timeout.handshake_timeout = to_duration(core_.settings.handshake_timeout_s);
    timeout.idle_timeout = websocket::stream_base::none();
    timeout.keep_alive_pings = false;
    ws_.set_option(timeout);
    ws_.read_message_max(hard_frame_limit(core_.settings.max_message_bytes));
    ws_.set_option(websocket::stream_base::decorator(
        [](websocket::response_type& res) { res.set(http::field::server, "carrom-server"); }));
    ws_.async_accept(request, beast::bind_front_handler(&WsSession::on_accept, shared_from_this()));
}

void WsSession::on_accept(beast::error_code ec) {
    if (ec) {
        spdlog::debug("websocket accept failed: {}", ec.message());
        return;
    }
    accepted_ = true;
    core_.metrics.connections_total.fetch_add(1, std::memory_order_relaxed);
    const auto open = core_.metrics.connections.fetch_add(1, std::memory_order_relaxed) + 1;
    core_.add_session(shared_from_this());
    last_activity_ms_ = core_.clock.now_ms();
    ws_.control_callback([this](websocket::frame_type kind, beast::string_view) {
        if (kind == websocket::frame_type::pong) {
            ping_in_flight_ = false;
        }
        last_activity_ms_ = core_.clock.now_ms();
    });
    if (open > core_.settings.max_connections || core_.stopping) {
        core_.metrics.rejected_connections_total.fetch_add(1, std::memory_order_relaxed);
        if (core_.stopping) {
            send_error(proto::code::kShuttingDown, kRestartingText);
            begin_close(proto::kCloseRestarting, "restarting");
        } else {
            fail(proto::code::kServerFull, "The server is full; try again later.",
                 proto::kCloseTryAgainLater);
        }
        do_read();
        return;
    }
    beast::error_code endpoint_ec;
    const auto remote = ws_.next_layer().next_layer().remote_endpoint(endpoint_ec);
    address_ = client_address(endpoint_ec ? std::string() : remote.address().to_string(),
                              forwarded_for_, core_.settings.trusted_proxies);
    if (!core_.add_address(address_)) {
        core_.metrics.rejected_connections_total.fetch_add(1, std::memory_order_relaxed);
        fail(proto::code::kTooManyConnections,
             "This address has " + std::to_string(core_.settings.max_connections_per_address) +
                 " connections open already; close one first.",
             proto::kClosePolicy);
        do_read();
        return;
    }
    address_counted_ = true;
    hello_timer_.expires_after(to_duration(core_.settings.handshake_timeout_s));
    hello_timer_.async_wait([self = shared_from_this()](beast::error_code timer_ec) {
        if (!timer_ec && !self->hello_done_ && !self->close_code_) {
            self->fail(proto::code::kHandshakeTimeout, "No hello arrived in time.",
                       proto::kClosePolicy);
        }
    });
    arm_idle_timer();
    do_read();
}

void WsSession::do_read() {
    ws_.async_read(buffer_, beast::bind_front_handler(&WsSession::on_read, shared_from_this()));
}

void WsSession::on_read(beast::error_code ec, std::size_t bytes) {
    if (ec) {
        if (ec == websocket::error::message_too_big) {
            core_.metrics.errors_sent_total.fetch_add(1, std::memory_order_relaxed);
        }
        end();
        return;
    }
    last_activity_ms_ = core_.clock.now_ms();
    core_.metrics.messages_in_total.fetch_add(1, std::memory_order_relaxed);
    core_.metrics.bytes_in_total.fetch_add(static_cast<std::int64_t>(bytes),
                                           std::memory_order_relaxed);
    const bool binary = ws_.got_binary();
    const std::string text = beast::buffers_to_string(buffer_.data());
    buffer_.consume(buffer_.size());
    if (!close_code_) {
        if (binary) {
            fail(proto::code::kBinaryFrame, "Only text frames are accepted.",
                 proto::kCloseUnsupportedData);
        } else if (text.size() > core_.settings.max_message_bytes) {
            fail(proto::code::kTooLarge,
                 "The message is " + std::to_string(text.size()) + " bytes; the limit is " +
                     std::to_string(core_.settings.max_message_bytes) + ".",
                 proto::kCloseTooBig);
        } else {
            switch (limiter_.on_message(core_.clock.now_ms())) {
            case RateLimiter::Verdict::Accept:
                handle_text(text);
                break;
            case RateLimiter::Verdict::Reject:
                send_error(proto::code::kRateLimited, "Too many messages; this one was ignored.");
                break;
            case RateLimiter::Verdict::Disconnect:
                fail(proto::code::kRateLimited, "Too many messages.", proto::kClosePolicy);
                break;
            }
        }
    }
    do_read();
}

void WsSession::handle_text(std::string_view text) {
    const auto decoded = proto::decode_client(text, core_.settings.max_message_bytes);
    if (!decoded.ok()) {
        send_error(decoded.error.code, decoded.error.message);
        return;
    }
    handle(*decoded.message);
}

void WsSession::handle(const proto::ClientMessage& message) {
    if (const auto* hello = std::get_if<proto::Hello>(&message)) {
        handle_hello(*hello);
        return;
    }
    if (!hello_done_) {
        send_error(proto::code::kHelloRequired, "Send hello first.");
        return;
    }
    if (hello_pending_) {
        // The resumed seat is being located in the cluster: this input follows the welcome.
        if (deferred_.size() < 16) {
            deferred_.push_back(message);
        }
        return;
    }
    if (const auto* ping = std::get_if<proto::Ping>(&message)) {
        send_now({std::make_shared<const std::string>(
                      proto::encode(proto::Pong{ping->nonce, core_.clock.now_ms()})),
                  room::MessageKind::Normal});
    } else if (const auto* create = std::get_if<proto::CreateRoom>(&message)) {
        handle_create(*create);
    } else if (const auto* join = std::get_if<proto::JoinRoom>(&message)) {
        handle_join(*join);
    } else if (const auto* quick = std::get_if<proto::QuickMatch>(&message)) {
        handle_quick_match(*quick);
    } else if (std::holds_alternative<proto::Leave>(message)) {
        stop_quick_match();
        if (room_) {
            room_->post([self = shared_from_this()](room::Room& room) { room.leave(*self); });
            room_.reset();
        }
    } else if (!room_) {
        send_error(proto::code::kNotInRoom, "Join a room first.");
    } else if (const auto* aim = std::get_if<proto::Aim>(&message)) {
        room_->post(
            [self = shared_from_this(), a = *aim](room::Room& room) { room.aim(*self, a); });
    } else if (const auto* shoot = std::get_if<proto::Shoot>(&message)) {
        room_->post(
            [self = shared_from_this(), s = *shoot](room::Room& room) { room.shoot(*self, s); });
    } else if (std::holds_alternative<proto::Rematch>(message)) {
        if (const auto refusal = core_.store_refusal()) { // a rematch would start a match
            send_error(refusal->code, refusal->message);
        } else {
            room_->post([self = shared_from_this()](room::Room& room) { room.rematch(*self); });
        }
    } else if (const auto* emote = std::get_if<proto::EmoteMessage>(&message)) {
        room_->post(
            [self = shared_from_this(), e = *emote](room::Room& room) { room.emote(*self, e); });
    }
}

// --- writing ----------------------------------------------------------------------------------

void WsSession::send(room::Outgoing message) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), m = std::move(message)]() mutable {
        self->send_now(std::move(m));
    });
}

void WsSession::send_now(room::Outgoing message) {
    if (ended_ || close_started_ || too_slow_ || !accepted_) {
        return;
    }
    switch (queue_.push(std::move(message))) {
    case WriteQueue::Push::Queued:
        break;
    case WriteQueue::Push::DroppedSnapshot:
        core_.metrics.snapshots_dropped_total.fetch_add(1, std::memory_order_relaxed);
        keyframe_request_ = true;
        break;
    case WriteQueue::Push::DroppedCue:
        core_.metrics.cues_dropped_total.fetch_add(1, std::memory_order_relaxed);
        break;
    case WriteQueue::Push::Overflow:
        // Counted once per client: nothing more is queued for it. What waits is dropped so that
        // the close frame follows the write in flight; a client that does not read even that
        // within kSlowKillAfter has its socket closed.
        too_slow_ = true;
        core_.metrics.slow_client_disconnects_total.fetch_add(1, std::memory_order_relaxed);
        spdlog::info("player {}: write queue full, disconnecting", player_id_);
        queue_.drop_waiting();
        begin_close(proto::kCloseSlowClient, "too_slow", kSlowKillAfter);
        return;
    }
    do_write();
}

void WsSession::send_error(std::string_view code, std::string message) {
    core_.metrics.errors_sent_total.fetch_add(1, std::memory_order_relaxed);
    send_now({std::make_shared<const std::string>(proto::encode_error(code, message)),
              room::MessageKind::Normal});
}

void WsSession::fail(std::string_view code, std::string message, int close_code) {
    send_error(code, message);
    begin_close(close_code, std::string(code));
}

void WsSession::close(int close_code, std::string reason) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), close_code, reason] {
        self->begin_close(close_code, reason);
    });
}

void WsSession::shutdown() {
    asio::post(ws_.get_executor(), [self = shared_from_this()] {
        self->send_error(proto::code::kShuttingDown, kRestartingText);
        self->begin_close(proto::kCloseRestarting, "restarting");
    });
}

void WsSession::begin_close(int close_code, std::string reason,
                            std::chrono::milliseconds deadline) {
    if (close_code_ || ended_) {
        return;
    }
    close_code_ = close_code;
    close_reason_ = std::move(reason);
    kill_timer_.expires_after(deadline);
    kill_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
        if (!ec && !self->ended_) {
            beast::error_code ignored;
            beast::get_lowest_layer(self->ws_).close(ignored);
        }
    });
    do_write();
}

void WsSession::do_write() {
    if (close_started_ || ended_) {
        return;
    }
    if (auto next = queue_.start_write()) {
        ws_.text(true);
        // The queue keeps the message (and its text) until finish_write.
        ws_.async_write(asio::buffer(*next->text),
                        [self = shared_from_this()](beast::error_code ec, std::size_t bytes) {
                            self->on_write(ec, bytes);
                        });
        return;
    }
    if (close_code_ && !queue_.writing()) {
        close_started_ = true;
        websocket::close_reason reason(static_cast<std::uint16_t>(*close_code_));
        reason.reason = close_reason_;
        ws_.async_close(reason, [self = shared_from_this()](beast::error_code) {
            beast::error_code ignored;
            beast::get_lowest_layer(self->ws_).close(ignored);
        });
    }
}

void WsSession::on_write(beast::error_code ec, std::size_t bytes) {
    queue_.finish_write();
    if (ec) {
        beast::error_code ignored;
        beast::get_lowest_layer(ws_).close(ignored);
        return;
    }
    core_.metrics.messages_out_total.fetch_add(1, std::memory_order_relaxed);
    core_.metrics.bytes_out_total.fetch_add(static_cast<std::int64_t>(bytes),
                                            std::memory_order_relaxed);
    do_write();
}

// --- keep-alive -------------------------------------------------------------------------------

void WsSession::arm_idle_timer() {
    const auto period =
        std::max(to_duration(core_.settings.idle_timeout_s / 4.0), std::chrono::milliseconds(20));
    idle_timer_.expires_after(period);
    idle_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
        if (!ec) {
            self->on_idle_timer();
        }
    });
}

void WsSession::on_idle_timer() {
    if (ended_ || close_code_) {
        return;
    }
    const auto idle_ms = core_.clock.now_ms() - last_activity_ms_;
    const auto limit_ms = to_duration(core_.settings.idle_timeout_s).count();
    if (idle_ms >= limit_ms) {
        fail(proto::code::kIdleTimeout, "Nothing arrived for too long.", proto::kClosePolicy);
        return;
    }
    if (idle_ms >= limit_ms / 2 && !ping_in_flight_) {
        ping_in_flight_ = true;
        ws_.async_ping({}, [self = shared_from_this()](beast::error_code) {});
    }
    arm_idle_timer();
}

// --- end --------------------------------------------------------------------------------------

void WsSession::end() {
    if (ended_) {
        return;
    }
    ended_ = true;
    hello_timer_.cancel();
    idle_timer_.cancel();
    kill_timer_.cancel();
    quick_timer_.cancel();
    quick_waiting_ = false;
    rated_timer_.cancel();
    rated_waiting_ = false;
    partner_timer_.cancel();
    withdraw_cluster_ticket();
    if (!accepted_) {
        return;
    }
    core_.metrics.connections.fetch_sub(1, std::memory_order_relaxed);
    core_.remove_session(this);
    if (address_counted_) {
        core_.remove_address(address_);
    }
    if (player_id_ >= 0) {
        core_.registry.cancel_quick_match(player_id_);
        core_.rated_queue.remove(player_id_);
    }
    if (room_) {
        room_->post([self = shared_from_this()](room::Room& room) { room.disconnected(*self); });
        room_.reset();
    } else if (!token_.empty()) {
        core_.registry.forget_player(token_);
    }
}

} // namespace carrom::server
