// The shared core and the room actors: each room's state is touched only on its strand.
#include "net_common.hpp"

#include "carrom/room/outcome_messages.hpp"

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include <cmath>

namespace carrom::server::net {

std::chrono::milliseconds to_duration(double seconds) {
    return std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(seconds * 1000.0)));
}

Core::Core(ServerSettings s, BotFactory b)
    : settings(std::move(s)), bots(std::move(b)), ioc(std::max(1, settings.threads)),
      registry(random, static_cast<std::size_t>(std::max(0, settings.max_rooms))) {}

std::variant<std::shared_ptr<RoomActor>, proto::Error>
Core::create_room(proto::RuleSet rule_set, const proto::RoomOptions& options) {
    room::RoomConfig config;
    config.rule_set = rule_set;
    config.rules = room::make_rules_config(rule_set, options, settings.shot_clock_s);
    config.snapshot_hz = settings.snapshot_hz;
    config.time_scale = settings.time_scale;
    config.grace_s = settings.grace_s;
    auto created = registry.create_room(
        [&](const std::string& code) { return std::make_shared<RoomActor>(*this, code, config); });
    if (std::holds_alternative<std::shared_ptr<RoomActor>>(created)) {
        metrics.rooms.fetch_add(1, std::memory_order_relaxed);
        spdlog::debug("room {} created ({})", std::get<std::shared_ptr<RoomActor>>(created)->code(),
                      proto::to_string(rule_set));
    }
    return created;
}

void Core::remove_room(const std::string& code) {
    registry.remove_room(code);
    metrics.rooms.fetch_sub(1, std::memory_order_relaxed);
    spdlog::debug("room {} closed", code);
}

RoomActor::RoomActor(Core& core, std::string code, room::RoomConfig config)
    : core_(core), code_(code), strand_(asio::make_strand(core.ioc)), timer_(strand_),
      room_(std::move(code), std::move(config), core.clock, core.metrics) {}

RoomActor::~RoomActor() = default;

void RoomActor::stop() {
    asio::post(strand_, [self = shared_from_this()] {
        self->removed_ = true;
        self->timer_.cancel();
    });
}

void RoomActor::after() {
    if (removed_) {
        return;
    }
    if (room_.abandoned()) {
        removed_ = true;
        timer_.cancel();
        core_.remove_room(code_);
        return;
    }
    if (auto turn = room_.take_bot_turn()) {
        // Bots think on bot_pool (one thread: at most one core for bots, the rest stays with the
        // I/O threads); a turn that queued behind other bots gets that much less time.
        const auto queued_at = std::chrono::steady_clock::now();
        asio::post(core_.bot_pool,
                   [self = shared_from_this(), t = std::move(*turn), queued_at]() mutable {
                       const auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(
                           std::chrono::steady_clock::now() - queued_at);
                       const Shot shot = t.brain->choose_shot(t.state, t.seat, waited);
                       asio::post(self->strand_, [self, seat = t.seat, turn_number = t.turn, shot] {
                           if (auto error = self->room_.bot_shoot(seat, turn_number, shot)) {
                               spdlog::warn("room {}: bot shot refused: {} ({})", self->code_,
                                            error->code, error->message);
                           }
                           self->after();
                       });
                   });
    }
    const auto wake = room_.next_wake_ms();
    if (!wake) {
        if (scheduled_ms_ >= 0) {
            scheduled_ms_ = -1;
            timer_.cancel();
        }
        return;
    }
    if (*wake != scheduled_ms_) {
        schedule(*wake);
    }
}

void RoomActor::schedule(std::int64_t wake_ms) {
    scheduled_ms_ = wake_ms;
    // SteadyClock counts whole milliseconds of steady_clock, so this fires when now_ms() >= wake.
    timer_.expires_at(std::chrono::steady_clock::time_point(std::chrono::milliseconds(wake_ms)));
    timer_.async_wait([self = shared_from_this(), wake_ms](boost::system::error_code ec) {
        if (ec || self->removed_ || self->scheduled_ms_ != wake_ms) {
            return;
        }
        self->scheduled_ms_ = -1;
        self->on_timer();
    });
}

void RoomActor::on_timer() {
    room_.tick();
    after();
}

} // namespace carrom::server::net
