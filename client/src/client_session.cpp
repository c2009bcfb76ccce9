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
      core_(config.backoff, net::ReconnectPolicy::Always, config.address),
      jitter_(config.jitter_seed.value_or(0)) {}

ReconnectInfo ClientSession::reconnect_info(double local_s) const {
    ReconnectInfo info;
    info.attempt = core_.tries();
    info.trying = link_ != nullptr;
    info.next_try_in_s = link_ ? 0.0 : std::max(0.0, core_.retry_at_s() - local_s);
    info.gives_up_in_s = std::max(0.0, core_.gives_up_at_s() - local_s);
    info.reason = lost_reason_;
    return info;
}

void ClientSession::start(double local_s) {
    now_s_ = local_s;
    apply(core_.start(""));
}

void ClientSession::apply(const net::SessionActions& actions) {
    using Kind = net::SessionActionKind;
    for (const net::SessionAction& action : actions) {
        switch (action.kind) {
        case Kind::Connect:
            open_link(now_s_);
            break;
        case Kind::SendHello:
        case Kind::SendResume: {
            proto::Hello hello;
            hello.name = name_;
            hello.identity = config_.identity;
            hello.follows_redirects = true;
            if (action.kind == Kind::SendResume) {
                hello.resume_token = core_.token();
            }
            link_->send(hello);
            status_ = "Saying hello...";
            break;
        }
        case Kind::SendRoomRequest:
            send_request();
            break;
        case Kind::SendJoin:
            link_->send(proto::JoinRoom{core_.join_code(), core_.join_as()});
            status_ = "Joining...";
            break;
        case Kind::SendLeave:
            if (link_ && link_->status().state == LinkState::Open) {
                link_->send(proto::Leave{});
            }
            break;
        case Kind::Wait:
            status_ = lost_reason_ + " Retrying in " + delay_text(action.wait_s) + " (attempt " +
                      std::to_string(core_.tries()) + ")";
            break;
        case Kind::Resumed:
            break;
        case Kind::SeatLost:
            seat_lost_ = true;
            request_.reset();
            status_ = "Connected (your old seat is gone: the server no longer holds it)";
            break;
        case Kind::Refused:
            request_.reset();
            status_ = "Connected";
            break;
        case Kind::GiveUp:
            if (link_) {
                link_->close();
                link_.reset();
            }
            switch (action.reason) {
            case net::GiveUpReason::VersionMismatch:
                status_ = "The server speaks another protocol version";
                break;
            case net::GiveUpReason::Replaced:
                status_ = "This seat was opened on another connection.";
                break;
            case net::GiveUpReason::TimeUp:
                status_ = lost_reason_ + " Gave up after " +
                          delay_text(now_s_ - core_.lost_since_s()) + ".";
                break;
            case net::GiveUpReason::NoRetry:
                status_ = lost_reason_;
                break;
            case net::GiveUpReason::RedirectRefused:
                status_ = core_.refused_redirect();
                lost_reason_ = status_;
                break;
            }
            break;
        }
    }
}

void ClientSession::open_link(double local_s) {
    if (link_) { // a redirect's: the server closes it (4005) once we go
        link_->close();
    }
    link_ = factory_ ? factory_(core_.url()) : nullptr;
    if (!link_) {
        on_link_lost(local_s, "Could not start a connection", 0);
        return;
    }
    hello_due_ = true;
    if (core_.redirects() > 0 && core_.tries() == 0) {
        status_ = "Moving to another server of the cluster...";
    } else if (core_.phase() == SessionPhase::Reconnecting) {
        status_ = "Reconnecting (attempt " + std::to_string(core_.tries()) + ")...";
    } else {
        status_ = "Connecting...";
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
    seat_lost_ = false;
    apply(core_.request());
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
    status_ = r.kind != RoomRequest::Kind::Quick ? "Joining..."
              : r.seats > 2                      ? "Waiting for players..."
                                                 : "Waiting for an opponent...";
}

bool ClientSession::send_game(const proto::ClientMessage& message) {
    if (phase() != SessionPhase::InRoom || !link_ || link_->status().state != LinkState::Open) {
        return false;
    }
    link_->send(message);
    return true;
}

void ClientSession::leave_room() {
    const bool in_room = phase() == SessionPhase::InRoom || phase() == SessionPhase::Joining;
    apply(core_.leave());
    request_.reset();
    if (in_room) {
        status_ = "Connected";
    }
}

void ClientSession::on_link_lost(double local_s, const std::string& why, int close_code) {
    if (link_) {
        link_->close();
        link_.reset();
    }
    if (core_.phase() == SessionPhase::Failed) {
        return;
    }
    lost_reason_ = as_sentence(why.empty() ? "The connection was lost" : why);
    const double jitter =
        config_.jitter_seed ? std::uniform_real_distribution<double>(0.0, 1.0)(jitter_) : 1.0;
    now_s_ = local_s;
    apply(core_.link_closed(local_s, close_code, jitter));
}

std::vector<proto::ServerMessage> ClientSession::update(double local_s) {
    now_s_ = local_s;
    std::vector<proto::ServerMessage> out;
    if (!link_) {
        apply(core_.tick(local_s));
        return out;
    }
    const LinkStatus st = link_->status();
    if (st.state == LinkState::Open && hello_due_) {
        hello_due_ = false;
        apply(core_.link_opened());
    }
    const MessageLink* polled = link_.get();
    for (proto::ServerMessage& m : link_->poll()) {
        if (handle(m)) {
            out.push_back(std::move(m));
        }
        if (link_.get() != polled) { // a redirect: the rest is the old link's
            return out;
        }
    }
    if (st.state == LinkState::Closed && link_) {
        on_link_lost(local_s, st.detail, st.close_code);
        return out;
    }
    const bool pinging = phase() == SessionPhase::Lobby || phase() == SessionPhase::Joining ||
                         phase() == SessionPhase::InRoom;
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

bool ClientSession::handle(const proto::ServerMessage& m) {
    if (core_.drops_room_messages() && is_room_message(m)) {
        return false; // from a room we left, sent before the server had our leave
    }
    if (const auto* welcome = std::get_if<proto::Welcome>(&m)) {
        player_id_ = welcome->player_id;
        status_ = "Connected";
        apply(core_.welcome(welcome->resume_token));
        return true;
    }
    if (std::holds_alternative<proto::RoomState>(m)) {
        status_ = "Connected";
        apply(core_.room_state());
        return true;
    }
    if (const auto* pong = std::get_if<proto::Pong>(&m)) {
        const auto it = pings_in_flight_.find(pong->nonce);
        if (it != pings_in_flight_.end()) {
            rtt_ms_ = std::max(now_s_ - it->second, 0.0) * 1000.0;
            pongs_.push_back({pong->server_time_ms, it->second, now_s_});
            pings_in_flight_.erase(it);
        }
        return false;
    }
    if (const auto* error = std::get_if<proto::Error>(&m)) {
        // The resume after a redirect that named its room finds no seat (a room whose match had
        // not begun keeps none): the session joins the room instead; nothing for the player.
        const bool joins_instead =
            error->code == proto::code::kBadToken && core_.resuming() && !core_.join_code().empty();
        apply(core_.error(error->code));
        return !joins_instead;
    }
    if (const auto* redirect = std::get_if<proto::Redirect>(&m)) {
        apply(core_.redirect(*redirect));
        return false;
    }
    return true;
}

std::vector<ClientSession::PongSample> ClientSession::take_pongs() {
    std::vector<PongSample> out;
    out.swap(pongs_);
    return out;
}

} // namespace carrom::client
