#include "carrom/client/demo_link.hpp"

#include "carrom/overloaded.hpp"
#include "carrom/proto/codec.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/proto/version.hpp"

#include <cmath>
#include <string>

namespace carrom::client {
namespace {

constexpr std::int64_t kPlayerId = 1;
constexpr const char* kToken = "0123456789abcdef0123456789abcdef";
constexpr const char* kRoomCode = "DEMXYZ"; // a valid room code (no 0, O, 1, I, L)

} // namespace

// The room's clock: the local clock in ms, shifted by the configured offset.
class DemoLink::LocalClock final : public room::Clock {
public:
    LocalClock(std::function<double()> seconds, std::int64_t offset_ms)
        : seconds_(std::move(seconds)), offset_ms_(offset_ms) {}
    std::int64_t now_ms() const override { return to_ms(seconds_()); }
    std::int64_t to_ms(double s) const {
        return static_cast<std::int64_t>(std::llround(s * 1000.0)) + offset_ms_;
    }
    double seconds() const { return seconds_(); }

private:
    std::function<double()> seconds_;
    std::int64_t offset_ms_;
};

// The player's end of the room: every message it receives is decoded as a client decodes a
// frame from the network, and waits in the inbox until the next poll.
class DemoLink::LocalPeer final : public room::Peer {
public:
    explicit LocalPeer(std::string name) : name_(std::move(name)) {}

    std::int64_t player_id() const override { return kPlayerId; }
    const std::string& name() const override { return name_; }
    void send(room::Outgoing message) override {
        auto decoded = proto::decode_server(*message.text);
        if (decoded.ok()) {
            inbox.push_back(std::move(*decoded.message));
        } else {
            ++unreadable;
        }
    }
    bool take_keyframe_request() override { return false; } // nothing is ever dropped
    void close(int, std::string) override { closed = true; }

    void rename(std::string name) { name_ = std::move(name); }

    std::vector<proto::ServerMessage> inbox;
    int unreadable = 0; // messages that did not decode (a bug in the room or the codec)
    bool closed = false;

private:
    std::string name_;
};

DemoLink::DemoLink(const PhysicsConfig& physics, std::function<double()> clock,
                   const DemoConfig& config)
    : physics_(physics), config_(config),
      clock_(std::make_unique<LocalClock>(std::move(clock), config.server_clock_offset_ms)),
      peer_(std::make_shared<LocalPeer>("Player")) {}

DemoLink::~DemoLink() = default;

LinkStatus DemoLink::status() const {
    LinkStatus status = open_ && !peer_->closed ? LinkStatus{LinkState::Open, "Offline demo"}
                                                : LinkStatus{LinkState::Closed, "The demo ended"};
    if (peer_->unreadable > 0) {
        status.detail += "; " + std::to_string(peer_->unreadable) +
                         " messages could not be read and were ignored.";
    }
    return status;
}

void DemoLink::close() {
    open_ = false;
}

void DemoLink::answer(const proto::ServerMessage& message) {
    peer_->send(
        {std::make_shared<const std::string>(proto::encode(message)), room::MessageKind::Normal});
}

void DemoLink::send(const proto::ClientMessage& message) {
    if (!open_) {
        return;
    }
    const double now = clock_->seconds();
    auto enter = [&](proto::RuleSet rule_set, const proto::RoomOptions& options) {
        if (room_) {
            answer(
                proto::Error{std::string(proto::code::kAlreadyInRoom), "Leave this room first."});
        } else {
            open_room(rule_set, options, now);
        }
    };
    std::visit(Overloaded{
                   [&](const proto::Hello& h) {
                       if (proto::is_player_name(h.name)) {
                           peer_->rename(h.name);
                       }
                       answer(proto::Welcome{proto::kProtocolVersion, kPlayerId, kToken,
                                             clock_->to_ms(now)});
                   },
                   [&](const proto::CreateRoom& c) { enter(c.rule_set, c.options); },
                   [&](const proto::JoinRoom&) { enter(proto::RuleSet::Icf, {}); },
                   [&](const proto::QuickMatch& q) { enter(q.rule_set, {}); },
                   [&](const proto::Aim& a) {
                       if (room_) {
                           room_->aim(*peer_, a);
                       }
                   },
                   [&](const proto::Shoot& s) {
                       if (room_) {
                           room_->shoot(*peer_, s);
                       }
                   },
                   [&](const proto::Rematch&) {
                       if (room_) {
                           room_->rematch(*peer_);
                       }
                   },
                   [&](const proto::Leave&) {
                       if (room_) {
                           room_->leave(*peer_);
                           room_.reset();
                       }
                       open_ = false;
                   },
                   [&](const proto::Ping& p) {
                       answer(proto::Pong{p.nonce, clock_->to_ms(now)});
                   },
                   [&](const proto::EmoteMessage& e) {
                       if (room_) {
                           room_->emote(*peer_, e);
                       }
                   },
               },
               message);
    note_turn(now);
}

std::vector<proto::ServerMessage> DemoLink::poll() {
    if (open_) {
        advance(clock_->seconds());
    }
    std::vector<proto::ServerMessage> out = std::move(peer_->inbox);
    peer_->inbox.clear();
    return out;
}

void DemoLink::open_room(proto::RuleSet rule_set, const proto::RoomOptions& options, double now_s) {
    room::RoomConfig config;
    config.rule_set = rule_set;
    config.rules = room::make_rules_config(rule_set, options, config_.shot_clock_s);
    config.rules.first_breaker = 1; // the opponent breaks
    config.physics = physics_;
    config.snapshot_hz = config_.snapshot_hz;
    room_ = std::make_unique<room::Room>(kRoomCode, config, *clock_, counters_);
    // Both seats fill here, so neither call can fail: the player takes seat 0, the opponent 1.
    (void)room_->join(peer_, proto::Role::Player);
    (void)room_->seat_bot("Demo bot", opponent_);
    first_break_ = true;
    turn_seen_ = -1;
    bot_turn_.reset();
    note_turn(now_s);
}

void DemoLink::note_turn(double now_s) {
    if (room_ && room_->phase() == proto::Phase::Aiming &&
        room_->match().turn_number != turn_seen_) {
        turn_seen_ = room_->match().turn_number;
        turn_seen_at_s_ = now_s;
    }
}

void DemoLink::advance(double now_s) {
    if (!room_) {
        return;
    }
    room_->tick();
    note_turn(now_s);
    if (!bot_turn_) {
        bot_turn_ = room_->take_bot_turn();
    }
    const rules::MatchState& match = room_->match();
    const double waited = now_s - turn_seen_at_s_;
    if (bot_turn_) {
        if (bot_turn_->turn != match.turn_number) {
            bot_turn_.reset(); // the shot clock passed that turn on
        } else if (waited >= (first_break_ ? config_.first_shot_at_s : config_.opponent_think_s)) {
            const room::BotTurn turn = std::move(*bot_turn_);
            bot_turn_.reset();
            first_break_ = false;
            const Shot shot = turn.brain->choose_shot(turn.state, turn.seat, {});
            // Refused only when no spot on the baseline is free: the shot clock passes the turn.
            (void)room_->bot_shoot(turn.seat, turn.turn, shot);
        }
        return;
    }
    const int seat = room_->seat_of(*peer_);
    if (config_.autoplay_after_s >= 0.0 && room_->phase() == proto::Phase::Aiming &&
        match.turn_seat == seat && waited >= config_.autoplay_after_s) {
        const Shot shot = DemoOpponent::shot_for(match, seat);
        room_->shoot(*peer_,
                     proto::Shoot{match.turn_number, shot.x_px, shot.angle_rad, shot.power});
    }
}

} // namespace carrom::client
