// WsSession in cluster mode (docs/cluster.md, "Rooms across the cluster"): a room or seat that
// another instance runs (redirect, or an error naming its URL), quick match across instances,
// and the move of a draining instance's rooms.
#include "ws_session.hpp"

#include "bot_seat_name.hpp"
#include "room_actor.hpp"
#include "server_core.hpp"

#include "carrom/proto/codec.hpp"

#include <boost/asio/post.hpp>
#include <spdlog/spdlog.h>

namespace carrom::server {

store::RoomLocation WsSession::reachable(store::RoomLocation where) const {
    // The front sent this client here although it asked for the owner's route: the front cannot
    // reach the owner (it died; its lease has not run out yet). A redirect would lead back here.
    if (where.where == store::RoomLocation::Where::Elsewhere && !route_asked_.empty() &&
        where.instance_id == route_asked_) {
        where.where = store::RoomLocation::Where::Moving;
    }
    return where;
}

void WsSession::redirect(proto::Redirect to) {
    core_.metrics.redirects_total.fetch_add(1, std::memory_order_relaxed);
    send_now({std::make_shared<const std::string>(proto::encode(to)), room::MessageKind::Normal});
    begin_close(proto::kCloseRedirected, "redirected");
}

void WsSession::locate_room(const proto::JoinRoom& join) {
    store::Cluster* cluster = core_.cluster();
    if (cluster == nullptr) {
        return;
    }
    cluster->locate_room(
        join.code, [self = shared_from_this(), join](store::Loaded<store::RoomLocation> located) {
            asio::post(self->ws_.get_executor(), [self, join, located = std::move(located)] {
                self->on_room_located(join, located);
            });
        });
}

void WsSession::on_room_located(const proto::JoinRoom& join,
                                const store::Loaded<store::RoomLocation>& located) {
    if (ended_ || close_code_ || room_) {
        return;
    }
    if (auto room = core_.registry.find_room(join.code)) {
        enter_room(room, join.as); // taken over here meanwhile
        return;
    }
    if (!located.ok()) {
        send_error(proto::code::kStoreUnavailable,
                   "Room " + join.code +
                       " cannot be looked up now: the server's database does not answer. Try "
                       "again in a moment.");
        return;
    }
    const store::RoomLocation where = reachable(located.value);
    switch (where.where) {
    case store::RoomLocation::Where::Elsewhere:
        if (follows_redirects_) {
            redirect(proto::Redirect{where.public_url, "room", join.code, join.as});
        } else {
            send_error(proto::code::kRoomElsewhere, "Room " + join.code +
                                                        " is on another server of this cluster: " +
                                                        where.public_url + " (connect there).");
        }
        return;
    case store::RoomLocation::Where::Moving:
        fail(proto::code::kMatchMoving,
             "Room " + join.code +
                 " is moving to another server of this cluster; try again in a few seconds.",
             proto::kCloseTryAgainLater);
        return;
    case store::RoomLocation::Where::Nowhere:
        break;
    }
    send_error(proto::code::kRoomNotFound, "No room has the code " + join.code + ".");
}

void WsSession::locate_seat(const proto::Hello& hello) {
    store::Cluster* cluster = core_.cluster();
    if (cluster == nullptr) {
        return;
    }
    hello_pending_ = true;
    cluster->locate_seat(
        store::hash_token(*hello.resume_token),
        [self = shared_from_this(), hello](store::Loaded<store::RoomLocation> located) {
            asio::post(self->ws_.get_executor(), [self, hello, located = std::move(located)] {
                self->on_seat_located(hello, located);
            });
        });
}

void WsSession::on_seat_located(const proto::Hello& hello,
                                const store::Loaded<store::RoomLocation>& located) {
    hello_pending_ = false;
    std::vector<proto::ClientMessage> deferred;
    deferred.swap(deferred_);
    if (ended_ || close_code_) {
        return;
    }
    // Taken over (or handed) to this instance meanwhile: the seat is here now.
    std::optional<PlayerRecord> record = core_.claim_restored_seat(*hello.resume_token);
    bool say_bad_token = true;
    if (!record && !located.ok()) {
        fail(proto::code::kMatchMoving,
             "Your seat cannot be looked up now: the server's database does not answer. Try "
             "again in a moment.",
             proto::kCloseTryAgainLater);
        return;
    }
    if (!record) {
        const store::RoomLocation where = reachable(located.value);
        if (where.where == store::RoomLocation::Where::Elsewhere) {
            if (follows_redirects_) {
                redirect(proto::Redirect{where.public_url, "seat", {}, proto::Role::Player});
            } else {
                fail(proto::code::kSeatElsewhere,
                     "Your seat's match (room " + where.room_code +
                         ") is on another server of this cluster: " + where.public_url +
                         " (resume there).",
                     proto::kCloseMatchMoved);
            }
            return;
        }
        if (!where.finished_match.empty()) {
            // Its last stroke was stored, not streamed, when its instance stopped.
            send_error(proto::code::kBadToken,
                       "Your match in room " + where.room_code +
                           " ended while you were away; its result: /matches/" +
                           where.finished_match + ". You join as a new player.");
            say_bad_token = false;
        } else if (where.where == store::RoomLocation::Where::Moving) {
            fail(proto::code::kMatchMoving,
                 "Your seat's match (room " + where.room_code +
                     ") is moving to another server of this cluster; try again in a few "
                     "seconds.",
                 proto::kCloseTryAgainLater);
            return;
        }
    }
    finish_hello(hello, std::move(record), say_bad_token);
    for (const auto& message : deferred) {
        handle(message);
    }
}

void WsSession::enqueue_in_cluster(proto::RuleSet rule_set) {
    store::Cluster* cluster = core_.cluster();
    if (cluster == nullptr || !follows_redirects_ || ticket_pending_) {
        return; // a client that cannot follow a redirect waits for players of this instance
    }
    store::QuickRequest request{std::string(proto::to_string(rule_set)), ticket_, std::nullopt};
    if (rated_waiting_ && identity_) {
        request.rated = store::RatedWait{rated_rating_, *identity_};
    } else if (ticket_ != 0) {
        return; // a guest's ticket waits as it is
    }
    ticket_pending_ = true;
    cluster->quick_enqueue(
        std::move(request), [self = shared_from_this(), generation = ticket_generation_,
                             rule_set](store::Loaded<store::QuickEnqueued> enqueued) {
            asio::post(self->ws_.get_executor(),
                       [self, generation, rule_set, enqueued = std::move(enqueued)] {
                           self->on_cluster_enqueued(generation, rule_set, enqueued);
                       });
        });
}

void WsSession::on_cluster_enqueued(std::uint64_t generation, proto::RuleSet rule_set,
                                    const store::Loaded<store::QuickEnqueued>& enqueued) {
    ticket_pending_ = false;
    if (!enqueued.ok()) {
        return; // the wait goes on here (players of this instance, then a bot)
    }
    // Still in this instance's queue, as when the ticket was asked for.
    const bool waiting = generation == ticket_generation_ && !ended_ && !close_code_ && !room_;
    if (!enqueued.value.paired) {
        ticket_ = enqueued.value.ticket;
        if (!waiting) {
            withdraw_cluster_ticket(); // paired here or gone meanwhile
            return;
        }
        const std::lock_guard lock(core_.tickets_mutex);
        core_.tickets[ticket_] = weak_from_this();
        return;
    }
    // Paired: this player's own ticket, if it had one, is gone with the pairing.
    if (ticket_ != 0) {
        const std::lock_guard lock(core_.tickets_mutex);
        core_.tickets.erase(std::exchange(ticket_, 0));
    }
    // A player of another instance is on the way to enqueued.room_code, to run here.
    const bool rated = rated_waiting_;
    const bool taken_out = rated ? core_.rated_queue.remove(player_id_)
                                 : core_.registry.cancel_quick_match(player_id_);
    if (!waiting || !taken_out) {
        // Paired here meanwhile: that player finds no room (room_not_found) and asks again.
        if (store::Cluster* cluster = core_.cluster()) {
            cluster->release_room_code(enqueued.value.room_code);
        }
        return;
    }
    stop_quick_match();
    spdlog::info("room {}: {}quick match with a player of another instance (ticket {})",
                 enqueued.value.room_code, rated ? "rated " : "", enqueued.value.ticket);
    host_cluster_pairing(rule_set, enqueued.value.room_code, rated);
}

void WsSession::host_cluster_pairing(proto::RuleSet rule_set, const std::string& code, bool rated) {
    auto created = core_.create_room(rule_set, proto::RoomOptions{}, 2, false, rated, code);
    if (auto* error = std::get_if<proto::Error>(&created)) {
        send_error(error->code, error->message);
        return;
    }
    auto room = std::get<std::shared_ptr<RoomActor>>(created);
    enter_room(room, proto::Role::Player);
    const double wait_s = core_.settings.quick_match_bot_s;
    if (wait_s <= 0.0 || !core_.bots) {
        return;
    }
    partner_timer_.expires_after(to_duration(wait_s));
    partner_timer_.async_wait(
        [self = shared_from_this(), room, rule_set, rated](beast::error_code ec) {
            if (ec) {
                return;
            }
            const auto level = self->core_.settings.quick_match_bot_level;
            if (!rated) { // the partner's seat goes to a bot
                room->post([brain = self->core_.bots(level), level](room::Room& r) {
                    (void)r.seat_bot(bot_seat_name(level, 1, 2), brain, 1); // refused once taken
                });
                return;
            }
            // A rated room takes no bot: this player leaves it for a room against one.
            room->post([self, room, rule_set, level](room::Room& r) {
                if (r.phase() != proto::Phase::Waiting || r.seat_of(*self) != 0) {
                    return; // the partner came (or this player left)
                }
                r.leave(*self);
                asio::post(self->ws_.get_executor(), [self, room, rule_set, level] {
                    if (self->room_ != room || self->ended_ || self->close_code_) {
                        return;
                    }
                    self->room_.reset();
                    self->enter_bot_room(rule_set, proto::RoomOptions{}, 2, level, {1});
                });
            });
        });
}

void WsSession::withdraw_cluster_ticket() {
    if (ticket_ == 0) {
        return;
    }
    const std::int64_t ticket = std::exchange(ticket_, 0);
    {
        const std::lock_guard lock(core_.tickets_mutex);
        core_.tickets.erase(ticket);
    }
    if (store::Cluster* cluster = core_.cluster()) {
        // Paired meanwhile (false): the other instance's room gives the seat to a bot.
        cluster->quick_withdraw(ticket, [](const store::Loaded<bool>&) {});
    }
}

void WsSession::on_quick_paired(store::QuickPairing pairing) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), pairing = std::move(pairing)] {
        if (self->ticket_ != pairing.ticket) {
            return;
        }
        self->ticket_ = 0; // consumed by the pairing instance
        if (self->room_ || self->ended_ || self->close_code_) {
            return; // paired here or gone: the other room's wait ends with a bot
        }
        const bool taken_out = self->rated_waiting_
                                   ? self->core_.rated_queue.remove(self->player_id_)
                                   : self->core_.registry.cancel_quick_match(self->player_id_);
        if (!taken_out) {
            return; // paired here meanwhile (its room is on its way)
        }
        self->stop_quick_match();
        self->redirect(proto::Redirect{pairing.room_url, "quick_match", pairing.room_code,
                                       proto::Role::Player});
    });
}

void WsSession::move_or_shutdown(
    std::shared_ptr<const std::unordered_map<std::string, std::string>> url_by_room) {
    asio::post(ws_.get_executor(), [self = shared_from_this(), url_by_room] {
        if (self->room_ && self->follows_redirects_) {
            const auto it = url_by_room->find(self->room_->code());
            if (it != url_by_room->end()) {
                self->redirect(proto::Redirect{it->second, "moved", it->first, self->role_});
                return;
            }
        }
        self->send_error(proto::code::kShuttingDown, kRestartingText);
        self->begin_close(proto::kCloseRestarting, "restarting");
    });
}

} // namespace carrom::server
