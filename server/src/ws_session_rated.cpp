// WsSession's identities and rated rooms (docs/ratings.md): the hello's key, the rated flag of
// create_room, a rated room's seats, and the rated quick-match queue paired by rating.
#include "ws_session.hpp"

#include "room_actor.hpp"
#include "server_core.hpp"

#include "carrom/proto/types.hpp"
#include "carrom/ratings/rating.hpp"

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include <chrono>

namespace carrom::server {

namespace {

constexpr std::chrono::seconds kRatedPairingTick{1}; // the rated queue is paired again this often

std::int64_t wall_clock_ms() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

proto::Error refusal(std::string_view code, std::string message) {
    return proto::Error{std::string(code), std::move(message)};
}

} // namespace

bool WsSession::admit_hello_identity(const proto::Hello& hello) {
    if (!hello.identity) {
        if (auto taken = core_.identities.check_guest_name(hello.name)) {
            send_error(taken->code, taken->message);
            return false;
        }
        identity_.reset();
        return true;
    }
    if (!proto::is_identity_key(*hello.identity)) {
        send_error(proto::code::kBadIdentity,
                   "identity must be a player key of 64 lowercase hexadecimal digits.");
        return false;
    }
    const store::PlayerKeyHash key_hash = store::hash_token(*hello.identity);
    auto claimed = core_.identities.claim(key_hash, hello.name, address_, wall_clock_ms(),
                                          core_.clock.now_ms());
    if (const auto* error = std::get_if<proto::Error>(&claimed)) {
        send_error(error->code, error->message);
        return false;
    }
    const auto& player = std::get<IdentityDirectory::Claimed>(claimed);
    if (player.changed && core_.store) {
        core_.store->save_player(player.player);
    }
    identity_ = key_hash;
    return true;
}

std::optional<proto::Error> WsSession::rated_refusal(const proto::CreateRoom& create) const {
    if (!create.rated) {
        return std::nullopt;
    }
    if (create.bot) {
        return refusal(proto::code::kRatedWithBot,
                       "A room with a bot seat is never rated; leave out rated or the bot.");
    }
    if (create.seats != 2) {
        return refusal(proto::code::kRatedDoubles,
                       "Doubles are not rated; a rated room has 2 seats.");
    }
    if (!identity_) {
        return refusal(proto::code::kIdentityRequired,
                       "A rated room needs a player key in hello; guests play unrated rooms.");
    }
    return std::nullopt;
}

std::optional<proto::Error> WsSession::rated_seat_refusal(RoomActor& room) const {
    if (!room.rated()) {
        return std::nullopt;
    }
    if (!identity_) {
        return refusal(proto::code::kIdentityRequired,
                       "This room is rated: its players need a player key in hello.");
    }
    if (!room.admit_identity(*identity_)) {
        return refusal(proto::code::kSamePlayer,
                       "Your player key already holds a seat in this rated room.");
    }
    return std::nullopt;
}

void WsSession::handle_rated_quick_match(const proto::QuickMatch& quick) {
    double rating = ratings::kInitialRating;
    if (core_.store) {
        for (const store::PlayerRating& r : core_.store->player_ratings(*identity_).value) {
            if (r.rule_set == proto::to_rules(quick.rule_set)) {
                rating = r.rating.rating;
            }
        }
    }
    const auto added = core_.rated_queue.add(
        quick.rule_set,
        RatedQueue::Entry{player_id_, *identity_, rating, core_.clock.now_ms(), weak_from_this()});
    if (added == RatedQueue::Added::SameIdentityWaiting) {
        send_error(proto::code::kSamePlayer,
                   "Your player key is already waiting for a quick match on another connection.");
        return;
    }
    if (added == RatedQueue::Added::Queued) {
        rated_waiting_ = true;
        rated_rule_set_ = quick.rule_set;
        rated_rating_ = rating;
        arm_quick_match_wait(quick.rule_set, 2);
        arm_rated_tick(quick_generation_);
    }
    if (!try_rated_pair(quick.rule_set) && rated_waiting_) {
        enqueue_in_cluster(quick.rule_set); // in a cluster: a player of another instance
    }
}

void WsSession::arm_rated_tick(std::uint64_t generation) {
    rated_timer_.expires_after(kRatedPairingTick);
    rated_timer_.async_wait([self = shared_from_this(), generation](beast::error_code ec) {
        if (ec || !self->rated_waiting_ || generation != self->quick_generation_) {
            return;
        }
        if (!self->try_rated_pair(self->rated_rule_set_) && self->rated_waiting_) {
            self->enqueue_in_cluster(self->rated_rule_set_); // the gap has widened
            self->arm_rated_tick(generation);
        }
    });
}

bool WsSession::try_rated_pair(proto::RuleSet rule_set) {
    if (core_.store_refusal()) {
        return false; // no match could start: both wait on (at the wait's end, store_unavailable)
    }
    auto pair = core_.rated_queue.pair(rule_set, core_.clock.now_ms());
    if (!pair) {
        return false;
    }
    auto first = pair->first.lock();
    auto second = pair->second.lock();
    if (!first || !second) {
        // A connection ended meanwhile: the other one waits again.
        for (const auto& survivor : {first, second}) {
            if (survivor) {
                asio::post(survivor->ws_.get_executor(), [survivor, rule_set] {
                    if (!survivor->room_ && !survivor->ended_) {
                        survivor->rated_waiting_ = false;
                        survivor->handle_rated_quick_match(proto::QuickMatch{rule_set, 2});
                    }
                });
            }
        }
        return first.get() == this || second.get() == this;
    }
    const bool mine = first.get() == this || second.get() == this;
    auto created = core_.create_room(rule_set, proto::RoomOptions{}, 2, false, true);
    if (auto* error = std::get_if<proto::Error>(&created)) {
        send_error(error->code, error->message);
        return mine;
    }
    auto room = std::get<std::shared_ptr<RoomActor>>(created);
    spdlog::debug("room {}: rated quick match", room->code());
    first->assign_room(room);
    second->assign_room(room);
    return mine;
}

void WsSession::on_rated_wait_over(proto::RuleSet rule_set) {
    rated_waiting_ = false;
    rated_timer_.cancel();
    if (!core_.rated_queue.remove(player_id_)) {
        return; // paired meanwhile: that room is on its way (assign_room)
    }
    enter_bot_room(rule_set, proto::RoomOptions{}, 2, core_.settings.quick_match_bot_level, {1});
}

} // namespace carrom::server
