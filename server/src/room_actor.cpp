#include "room_actor.hpp"

#include "server_core.hpp"
#include "waiting_room.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <utility>

namespace carrom::server {

RoomActor::RoomActor(ServerCore& core, std::string code, room::RoomConfig config)
    : core_(core), code_(code), strand_(asio::make_strand(core.ioc)), timer_(strand_),
      logger_(code),
      journal_(core.store
                   ? std::make_unique<StoreJournal>(core.store, core.random, core.stopping, rated_,
                                                    [&core](const std::string& token) {
                                                        return core.registry.identity_of(token);
                                                    })
                   : nullptr),
      room_(std::move(code), std::move(config), core.clock, core.metrics, &logger_,
            journal_.get()) {}

void RoomActor::bind_journal() {
    if (!journal_) {
        return;
    }
    journal_->on_written([weak = weak_from_this(), gate = core_.confirmations](
                             const std::string& match_id, std::int64_t seq) {
        gate->pass([&] {
            if (auto self = weak.lock()) {
                asio::post(self->strand_, [self, match_id, seq] {
                    if (self->lost_) {
                        return; // nothing of a stroke of a lost match streams
                    }
                    self->room_.journal_written(match_id, seq);
                    self->after();
                });
            }
        });
    });
}

RoomActor::~RoomActor() = default;

bool RoomActor::admit_identity(const store::PlayerKeyHash& key_hash) {
    const std::lock_guard lock(identities_mutex_);
    if (std::find(identities_.begin(), identities_.end(), key_hash) != identities_.end()) {
        return false;
    }
    identities_.push_back(key_hash);
    return true;
}

std::optional<std::string> RoomActor::restore(const proto::MatchJournal& journal,
                                              std::vector<room::RestoredSeat> seats) {
    if (auto refused = room_.restore(journal, std::move(seats))) {
        return refused;
    }
    asio::post(strand_, [self = shared_from_this()] { self->after(); });
    return std::nullopt;
}

void RoomActor::restore_on_strand(proto::MatchJournal journal,
                                  std::vector<room::RestoredSeat> seats,
                                  std::function<void(bool restored)> on_done) {
    asio::post(strand_, [self = shared_from_this(), journal = std::move(journal),
                         seats = std::move(seats), on_done = std::move(on_done)]() mutable {
        if (auto refused = self->room_.restore(journal, std::move(seats))) {
            spdlog::warn("match {} not taken over (left in the store): {}",
                         journal.created.match_id, *refused);
            self->removed_ = true;
            self->core_.registry.remove_room(self->code_); // and the claims for its seats
            on_done(false);
            return;
        }
        on_done(true);
        self->after();
    });
}

std::future<void> RoomActor::settled() {
    auto done = std::make_shared<std::promise<void>>();
    auto future = done->get_future();
    asio::post(strand_, [done] { done->set_value(); });
    return future;
}

void RoomActor::remove_if_nobody_came(std::chrono::milliseconds wait) {
    auto timer = std::make_shared<asio::steady_timer>(strand_, wait);
    timer->async_wait([self = shared_from_this(), timer](const boost::system::error_code& ec) {
        if (ec || self->lost_ || self->removed_ || !self->room_.abandoned()) {
            return;
        }
        spdlog::info("room {}: nobody came back to it", self->code_);
        self->removed_ = true;
        self->timer_.cancel();
        self->core_.remove_room(self->code_);
    });
}

std::future<std::optional<store::WaitingRoom>> RoomActor::freeze() {
    auto frozen = std::make_shared<std::promise<std::optional<store::WaitingRoom>>>();
    auto future = frozen->get_future();
    asio::post(strand_, [self = shared_from_this(), frozen] {
        const bool was_lost = std::exchange(self->lost_, true);
        self->removed_ = true;
        self->timer_.cancel();
        std::optional<store::WaitingRoom> waiting;
        if (!was_lost && self->room_.waiting_for_players()) {
            const room::RoomConfig& config = self->room_.config();
            waiting = store::WaitingRoom{
                self->code_, describe_waiting_room({config.rule_set, config.rules, self->rated()})};
        }
        frozen->set_value(std::move(waiting));
    });
    return future;
}

void RoomActor::lose() {
    asio::post(strand_, [self = shared_from_this()] {
        if (self->lost_) {
            return;
        }
        self->lost_ = true;
        self->timer_.cancel();
        self->room_.close_connections(proto::kCloseMatchMoved, "match_moved");
        if (!self->removed_) {
            self->removed_ = true;
            self->core_.remove_room(self->code_);
        }
    });
}

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
        asio::post(core_.bot_pool, [self = shared_from_this(), t = std::move(*turn),
                                    queued_at]() mutable {
            const auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(
                std::chrono::steady_clock::now() - queued_at);
            const Shot shot = t.brain->choose_shot(t.state, t.seat, waited);
            asio::post(self->strand_, [self, seat = t.seat, turn_number = t.turn, shot] {
                if (self->lost_) {
                    return;
                }
                const room::BotShotOutcome outcome = self->room_.bot_shoot(seat, turn_number, shot);
                if (outcome.refused) {
                    spdlog::warn("room {}: bot shot refused: {} ({})", self->code_,
                                 outcome.refused->code, outcome.refused->message);
                } else if (outcome.replaced) {
                    spdlog::warn("room {}: bot shot played as the nearest legal one: "
                                 "{} ({})",
                                 self->code_, outcome.replaced->code, outcome.replaced->message);
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
    if (lost_) {
        return;
    }
    room_.tick();
    after();
}

} // namespace carrom::server
