// WsSession before and between rooms: hello (new, or a resume with its token), create_room,
// join_room, quick_match and its wait for partners (then bots), entering a room.
#include "ws_session.hpp"

#include "bot_seat_name.hpp"

#include "room_actor.hpp"
#include "server_core.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/proto/limits.hpp"
#include "carrom/proto/version.hpp"

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>

namespace carrom::server {

void WsSession::handle_hello(const proto::Hello& hello) {
    if (hello_done_) {
        send_error(proto::code::kAlreadyHello, "This connection already said hello.");
        return;
    }
    if (hello.version != proto::kProtocolVersion) {
        fail(proto::code::kVersionMismatch,
             "The server speaks protocol version " + std::to_string(proto::kProtocolVersion) +
                 "; the client sent " + std::to_string(hello.version) + ".",
             proto::kCloseVersionMismatch);
        return;
    }
    if (!admit_hello_identity(hello)) {
        return; // refused; the client may say hello again before the hello timeout
    }
    hello_done_ = true;
    hello_timer_.cancel();
    name_ = hello.name;
    follows_redirects_ = hello.follows_redirects;
    std::optional<PlayerRecord> record;
    if (hello.resume_token) {
        record = core_.registry.find_player(*hello.resume_token);
        if (!record) {
            // A seat of a match recovered after a restart (docs/store.md, "Recovery after a
            // restart"): the store kept the token's hash.
            record = core_.claim_restored_seat(*hello.resume_token);
        }
        if (!record && core_.cluster()) {
            locate_seat(hello); // another instance may run the seat's match
            return;
        }
    }
    finish_hello(hello, std::move(record), true);
}

void WsSession::finish_hello(const proto::Hello& hello, std::optional<PlayerRecord> record,
                             bool say_bad_token) {
    if (hello.resume_token && !record && say_bad_token) {
        send_error(proto::code::kBadToken,
                   "That resume token is unknown or expired; you join as a new player.");
    }
    if (!record) {
        record = core_.registry.new_player();
    }
    player_id_ = record->player_id;
    token_ = record->token;
    core_.registry.set_player_identity(token_, identity_);
    send_now({std::make_shared<const std::string>(proto::encode(proto::Welcome{
                  proto::kProtocolVersion, player_id_, token_, core_.clock.now_ms()})),
              room::MessageKind::Normal});
    if (!hello.resume_token || record->room_code.empty()) {
        return;
    }
    auto room = core_.registry.find_room(record->room_code);
    if (!room) {
        send_error(proto::code::kBadToken, "That room has closed.");
        return;
    }
    room_ = room;
    room->post([self = shared_from_this(), room](room::Room& r) {
        if (auto error = r.resume(self)) {
            self->on_room_refused(room, *error);
        }
    });
}

void WsSession::handle_create(const proto::CreateRoom& create) {
    if (room_) {
        send_error(proto::code::kAlreadyInRoom, "Leave this room first.");
        return;
    }
    if (auto refusal = rated_refusal(create)) {
        send_error(refusal->code, refusal->message);
        return;
    }
    if (create.bot) {
        if (!core_.bots) {
            send_error(proto::code::kUnsupported, "This server has no bots.");
            return;
        }
        std::vector<int> bot_seats = create.bot->seats; // the decoder checked them
        if (bot_seats.empty()) {
            for (int seat = 1; seat < create.seats; ++seat) {
                bot_seats.push_back(seat); // every seat but the creator's
            }
        }
        enter_bot_room(create.rule_set, create.options, create.seats, create.bot->level, bot_seats);
        return;
    }
    auto created =
        core_.create_room(create.rule_set, create.options, create.seats, false, create.rated);
    if (auto* error = std::get_if<proto::Error>(&created)) {
        send_error(error->code, error->message);
        return;
    }
    enter_room(std::get<std::shared_ptr<RoomActor>>(created), proto::Role::Player);
}

void WsSession::enter_bot_room(proto::RuleSet rule_set, const proto::RoomOptions& options,
                               int seats, proto::BotLevel level, const std::vector<int>& bot_seats,
                               const std::vector<std::shared_ptr<WsSession>>& others) {
    std::vector<std::pair<int, std::shared_ptr<room::BotBrain>>> bots;
    for (const int seat : bot_seats) {
        bots.emplace_back(seat, core_.bots(level));
    }
    auto created = core_.create_room(rule_set, options, seats, true);
    if (auto* error = std::get_if<proto::Error>(&created)) {
        send_error(error->code, error->message);
        return;
    }
    auto room = std::get<std::shared_ptr<RoomActor>>(created);
    // This player's join is posted first, so it takes seat 0; the bots take their own seats and
    // the others (posted later, from their own threads) the first free ones.
    enter_room(room, proto::Role::Player);
    for (const auto& other : others) {
        other->assign_room(room);
    }
    room->post([bots = std::move(bots), level, seats](room::Room& r) {
        for (const auto& [seat, brain] : bots) {
            (void)r.seat_bot(bot_seat_name(level, seat, seats), brain, seat);
        }
    });
}

void WsSession::handle_join(const proto::JoinRoom& join) {
    if (room_) {
        send_error(proto::code::kAlreadyInRoom, "Leave this room first.");
        return;
    }
    auto room = core_.registry.find_room(join.code);
    if (!room && core_.cluster()) {
        locate_room(join); // another instance may run it
        return;
    }
    if (!room) {
        send_error(proto::code::kRoomNotFound, "No room has the code " + join.code + ".");
        return;
    }
    enter_room(room, join.as);
}

void WsSession::enter_room(const std::shared_ptr<RoomActor>& room, proto::Role role) {
    if (role == proto::Role::Player) {
        if (auto refusal = rated_seat_refusal(*room)) {
            send_error(refusal->code, refusal->message);
            return;
        }
    }
    stop_quick_match();
    room_ = room;
    role_ = role;
    if (role == proto::Role::Player) {
        core_.registry.set_player_room(token_, room->code());
    }
    room->post([self = shared_from_this(), room, role](room::Room& r) {
        if (auto error = r.join(self, role)) {
            self->on_room_refused(room, *error);
        }
    });
}

void WsSession::on_room_refused(const std::shared_ptr<RoomActor>& room, const proto::Error& error) {
    send({std::make_shared<const std::string>(proto::encode(error)), room::MessageKind::Normal});
    asio::post(ws_.get_executor(), [self = shared_from_this(), room] {
        if (self->room_ == room) {
            self->room_.reset();
        }
    });
}

void WsSession::handle_quick_match(const proto::QuickMatch& quick) {
    if (room_) {
        send_error(proto::code::kAlreadyInRoom, "Leave this room first.");
        return;
    }
    if (const auto refusal = core_.store_refusal()) { // no queue: no match could start
        send_error(refusal->code, refusal->message);
        return;
    }
    if (identity_ && quick.seats == 2) {
        handle_rated_quick_match(quick);
        return;
    }
    for (;;) {
        auto group =
            core_.registry.quick_match(quick.rule_set, quick.seats, player_id_, weak_from_this());
        if (!group) {
            // Queued (or already queued): paired when the next player asks, or given a bot once
            // the wait is over. A repeated quick_match keeps the first wait. In a cluster, a
            // player waiting on another instance may be paired too.
            arm_quick_match_wait(quick.rule_set, quick.seats);
            if (quick.seats == 2) {
                enqueue_in_cluster(quick.rule_set);
            }
            return;
        }
        std::vector<std::shared_ptr<WsSession>> partners;
        for (const auto& ref : *group) {
            if (auto partner = ref.lock()) {
                partners.push_back(std::move(partner));
            }
        }
        if (partners.empty()) {
            continue; // those players left; try the next ones
        }
        const int humans = 1 + static_cast<int>(partners.size());
        if (humans < quick.seats && core_.bots) {
            // A player of the group left meanwhile: a bot takes that seat.
            std::vector<int> bot_seats;
            for (int seat = humans; seat < quick.seats; ++seat) {
                bot_seats.push_back(seat);
            }
            enter_bot_room(quick.rule_set, proto::RoomOptions{}, quick.seats,
                           core_.settings.quick_match_bot_level, bot_seats, partners);
            return;
        }
        auto created = core_.create_room(quick.rule_set, proto::RoomOptions{}, quick.seats);
        if (auto* error = std::get_if<proto::Error>(&created)) {
            send_error(error->code, error->message);
            return;
        }
        auto room = std::get<std::shared_ptr<RoomActor>>(created);
        for (const auto& partner : partners) {
            partner->assign_room(room);
        }
        enter_room(room, proto::Role::Player);
        return;
    }
}

void WsSession::arm_quick_match_wait(proto::RuleSet rule_set, int seats) {
    const double wait_s = core_.settings.quick_match_bot_s;
    if (quick_waiting_ || wait_s <= 0.0 || !core_.bots) {
        return;
    }
    quick_waiting_ = true;
    const auto generation = ++quick_generation_;
    quick_timer_.expires_after(to_duration(wait_s));
    quick_timer_.async_wait(
        [self = shared_from_this(), generation, rule_set, seats](beast::error_code ec) {
            if (!ec) {
                self->on_quick_match_wait(generation, rule_set, seats);
            }
        });
}

void WsSession::stop_quick_match() {
    ++ticket_generation_;
    withdraw_cluster_ticket();
    if (player_id_ >= 0) {
        (void)core_.registry.cancel_quick_match(player_id_);
        (void)core_.rated_queue.remove(player_id_);
    }
    if (rated_waiting_) {
        rated_waiting_ = false;
        rated_timer_.cancel();
    }
    if (quick_waiting_) {
        quick_waiting_ = false;
        ++quick_generation_;
        quick_timer_.cancel();
    }
}

void WsSession::on_quick_match_wait(std::uint64_t generation, proto::RuleSet rule_set, int seats) {
    if (generation != quick_generation_ || !quick_waiting_) {
        return; // cancelled, or a newer wait
    }
    quick_waiting_ = false;
    if (ended_ || close_code_ || room_) {
        return;
    }
    if (rated_waiting_) {
        on_rated_wait_over(rule_set);
        return;
    }
    // Only a player still in the queue gets bots: if a partner took it out first, that
    // partner's room is on its way (assign_room). The players waiting for the same mode come
    // along (doubles: 1 to 3 players), bots take the other seats.
    auto others = core_.registry.take_waiting(rule_set, seats, player_id_);
    if (!others) {
        return;
    }
    std::vector<std::shared_ptr<WsSession>> partners;
    for (const auto& ref : *others) {
        if (auto partner = ref.lock()) {
            partners.push_back(std::move(partner));
        }
    }
    std::vector<int> bot_seats;
    for (int seat = 1 + static_cast<int>(partners.size()); seat < seats; ++seat) {
        bot_seats.push_back(seat);
    }
    spdlog::debug("player {}: quick-match wait over, {} players and {} bots", player_id_,
                  1 + partners.size(), bot_seats.size());
    enter_bot_room(rule_set, proto::RoomOptions{}, seats, core_.settings.quick_match_bot_level,
                   bot_seats, partners);
}

void WsSession::assign_room(std::shared_ptr<RoomActor> room) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), room] {
        if (!self->room_ && !self->ended_ && !self->close_code_) {
            self->enter_room(room, proto::Role::Player);
        }
    });
}

} // namespace carrom::server
