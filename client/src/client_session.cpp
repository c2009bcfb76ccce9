#include "carrom/client/client_session.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace carrom::client {
namespace {

// `text` as a sentence: with a full stop unless it already ends with one (links give sentences).
std::string as_sentence(const std::string& text) {
    if (!text.empty() && (text.back() == '.' || text.back() == '!' || text.back() == '?')) {
        return text;
    }
    return text + ".";
}

// Errors that answer a room request with no: the player picks something else in the lobby.
bool refuses_request(const std::string& code) {
    return code == proto::code::kRoomNotFound || code == proto::code::kRoomFull ||
           code == proto::code::kUnsupported || code == proto::code::kTooManyRooms ||
           code == proto::code::kBadField;
}

std::string delay_text(double s) {
    std::ostringstream out;
    out.precision(s < 10.0 ? 1 : 0);
    out << std::fixed << s << " s";
    return out.str();
}

// Whether a message belongs to a room (as opposed to the connection).
bool is_room_message(const proto::ServerMessage& m) {
    return std::holds_alternative<proto::RoomState>(m) ||
           std::holds_alternative<proto::Snapshot>(m) || std::holds_alternative<proto::Event>(m) ||
           std::holds_alternative<proto::ShotResult>(m);
}

} // namespace

ClientSession::ClientSession(LinkFactory factory, std::string name, const SessionConfig& config)
    : factory_(std::move(factory)), name_(std::move(name)), config_(config),
      jitter_(config.jitter_seed.value_or(0)) {}

ReconnectInfo ClientSession::reconnect_info(double local_s) const {
    ReconnectInfo info;
    info.attempt = attempts_;
    info.trying = link_ != nullptr;
    info.next_try_in_s = link_ ? 0.0 : std::max(0.0, retry_at_s_ - local_s);
    info.gives_up_in_s = std::max(0.0, lost_since_s_ + config_.give_up_after_s - local_s);
    info.reason = lost_reason_;
    return info;
}

void ClientSession::start(double local_s) {
    open_link(local_s);
}

void ClientSession::open_link(double local_s) {
    link_ = factory_ ? factory_() : nullptr;
    if (!link_) {
        on_link_lost(local_s, "Could not start a connection");
        return;
    }
    if (phase_ != SessionPhase::Reconnecting) {
        phase_ = SessionPhase::Connecting;
        status_ = "Connecting...";
    } else {
        status_ = "Reconnecting (attempt " + std::to_string(attempts_) + ")...";
    }
}

std::string check_room_request(const RoomRequest& request) {
    if (request.seats != 2 && request.seats != 4) {
        return "--seats must be 2 or 4 (got " + std::to_string(request.seats) + ").";
    }
    if (!request.bot) {
        return "";
    }
    const std::vector<int>& seats = request.bot->seats;
    for (std::size_t i = 0; i < seats.size(); ++i) {
        if (seats[i] < 1 || seats[i] >= request.seats) {
            return "--bot-seats: seat " + std::to_string(seats[i]) + " is not one of 1.." +
                   std::to_string(request.seats - 1) + " (seat 0 is yours).";
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (seats[j] == seats[i]) {
                return "--bot-seats: seat " + std::to_string(seats[i]) + " is named twice.";
            }
        }
    }
    return "";
}

void ClientSession::request(const RoomRequest& request) {
    request_ = request;
    request_sent_ = false;
    seat_lost_ = false;
    if (phase_ == SessionPhase::Lobby) {
        send_request();
    }
}

void ClientSession::send_request() {
    if (!request_ || !link_) {
        return;
    }
    const RoomRequest& r = *request_;
    switch (r.kind) {
    case RoomRequest::Kind::Create: {
        proto::CreateRoom create;
        create.rule_set = r.rule_set;
        create.seats = r.seats;
        create.bot = r.bot;
        link_->send(create);
        break;
    }
    case RoomRequest::Kind::Join:
        link_->send(proto::JoinRoom{r.code, proto::Role::Player});
        break;
    case RoomRequest::Kind::Spectate:
        link_->send(proto::JoinRoom{r.code, proto::Role::Spectator});
        break;
    case RoomRequest::Kind::Quick: {
        proto::QuickMatch quick;
        quick.rule_set = r.rule_set;
        quick.seats = r.seats;
        link_->send(quick);
        break;
    }
    }
    request_sent_ = true;
    left_room_ = false;
    phase_ = SessionPhase::Joining;
    status_ = r.kind != RoomRequest::Kind::Quick ? "Joining..."
              : r.seats > 2                      ? "Waiting for players..."
                                                 : "Waiting for an opponent...";
}

bool ClientSession::send_game(const proto::ClientMessage& message) {
    if (phase_ != SessionPhase::InRoom || !link_ || link_->status().state != LinkState::Open) {
        return false;
    }
    link_->send(message);
    return true;
}

void ClientSession::leave_room() {
    if (link_ && link_->status().state == LinkState::Open &&
        (phase_ == SessionPhase::InRoom || phase_ == SessionPhase::Joining)) {
        link_->send(proto::Leave{});
    }
    request_.reset();
    request_sent_ = false;
    left_room_ = true;
    resuming_ = false; // a reconnect says hello as a new player, without the old seat
    if (phase_ == SessionPhase::InRoom || phase_ == SessionPhase::Joining) {
        phase_ = SessionPhase::Lobby;
        status_ = "Connected";
    }
}

void ClientSession::on_link_lost(double local_s, const std::string& why) {
    if (link_) {
        link_->close();
        link_.reset();
    }
    if (phase_ == SessionPhase::Failed) {
        return;
    }
    const bool was_connected = attempts_ == 0;
    if (was_connected) {
        lost_since_s_ = local_s;
    }
    ++attempts_;
    const std::string reason = as_sentence(why.empty() ? "The connection was lost" : why);
    lost_reason_ = reason;
    if (local_s - lost_since_s_ >= config_.give_up_after_s) {
        phase_ = SessionPhase::Failed;
        status_ = reason + " Gave up after " + delay_text(local_s - lost_since_s_) + ".";
        return;
    }
    retry_delay_s_ = attempts_ == 1 ? config_.first_retry_s
                                    : std::min(2.0 * retry_delay_s_, config_.max_retry_s);
    double delay = retry_delay_s_;
    if (config_.jitter_seed) {
        delay = std::uniform_real_distribution<double>(delay / 2.0, delay)(jitter_);
    }
    retry_at_s_ = local_s + delay;
    resuming_ = resuming_ || (!token_.empty() &&
                              (phase_ == SessionPhase::InRoom || phase_ == SessionPhase::Joining));
    phase_ = ever_welcomed_ ? SessionPhase::Reconnecting : SessionPhase::Connecting;
    status_ = reason + " Retrying in " + delay_text(delay) + " (attempt " +
              std::to_string(attempts_) + ")";
}

std::vector<proto::ServerMessage> ClientSession::update(double local_s) {
    std::vector<proto::ServerMessage> out;
    if (!link_) {
        if ((phase_ == SessionPhase::Connecting || phase_ == SessionPhase::Reconnecting) &&
            local_s >= retry_at_s_) {
            open_link(local_s);
        }
        return out;
    }
    const LinkStatus st = link_->status();
    if (st.state == LinkState::Open &&
        (phase_ == SessionPhase::Connecting || phase_ == SessionPhase::Reconnecting)) {
        proto::Hello hello;
        hello.name = name_;
        if (resuming_) {
            hello.resume_token = token_;
        }
        link_->send(hello);
        phase_ = SessionPhase::Greeting;
        status_ = "Saying hello...";
    }
    for (proto::ServerMessage& m : link_->poll()) {
        if (handle(m, local_s)) {
            out.push_back(std::move(m));
        }
    }
    if (st.state == LinkState::Closed && link_) {
        on_link_lost(local_s, st.detail);
        return out;
    }
    const bool pinging = phase_ == SessionPhase::Lobby || phase_ == SessionPhase::Joining ||
                         phase_ == SessionPhase::InRoom;
    if (pinging && local_s >= next_ping_s_ && link_) {
        const std::int64_t nonce = next_nonce_++;
        pings_in_flight_[nonce] = local_s;
        while (pings_in_flight_.size() > 16) {
            pings_in_flight_.erase(pings_in_flight_.begin());
        }
        link_->send(proto::Ping{nonce});
        next_ping_s_ = local_s + config_.ping_interval_s;
    }
    return out;
}

bool ClientSession::handle(const proto::ServerMessage& m, double local_s) {
    if (left_room_ && is_room_message(m)) {
        return false; // from a room we left, sent before the server had our leave
    }
    if (const auto* welcome = std::get_if<proto::Welcome>(&m)) {
        token_ = welcome->resume_token;
        player_id_ = welcome->player_id;
        ever_welcomed_ = true;
        attempts_ = 0;
        status_ = "Connected";
        if (resuming_) {
            phase_ = SessionPhase::Joining; // the server sends the room back
        } else {
            phase_ = SessionPhase::Lobby;
            if (request_) {
                send_request();
            }
        }
        return true;
    }
    if (std::holds_alternative<proto::RoomState>(m)) {
        phase_ = SessionPhase::InRoom;
        resuming_ = false;
        status_ = "Connected";
        return true;
    }
    if (const auto* pong = std::get_if<proto::Pong>(&m)) {
        const auto it = pings_in_flight_.find(pong->nonce);
        if (it != pings_in_flight_.end()) {
            rtt_ms_ = std::max(local_s - it->second, 0.0) * 1000.0;
            pongs_.push_back({pong->server_time_ms, it->second, local_s});
            pings_in_flight_.erase(it);
        }
        return false;
    }
    if (const auto* error = std::get_if<proto::Error>(&m)) {
        if (error->code == proto::code::kVersionMismatch) {
            phase_ = SessionPhase::Failed;
            status_ = "The server speaks another protocol version";
        } else if (error->code == proto::code::kBadToken) {
            seat_lost_ = seat_lost_ || resuming_;
            resuming_ = false;
            token_.clear();
            phase_ = SessionPhase::Lobby;
            request_.reset();
            status_ = "Connected (your old seat is gone: the server no longer holds it)";
        } else if (phase_ == SessionPhase::Joining && refuses_request(error->code)) {
            phase_ = SessionPhase::Lobby;
            request_.reset();
            status_ = "Connected";
        }
        return true;
    }
    return true;
}

std::vector<ClientSession::PongSample> ClientSession::take_pongs() {
    std::vector<PongSample> out;
    out.swap(pongs_);
    return out;
}

} // namespace carrom::client
