#include "carrom/net/session_core.hpp"

#include "carrom/enum_names.hpp"

#include "carrom/net/redirect_rule.hpp"
#include "carrom/proto/error.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace carrom::net {
namespace {

// Errors that answer a room request with no: the session goes back to the lobby.
bool refuses_request(std::string_view code) {
    namespace c = proto::code;
    return code == c::kRoomNotFound || code == c::kRoomFull || code == c::kUnsupported ||
           code == c::kTooManyRooms || code == c::kBadField || code == c::kAlreadyInRoom;
}

// A URL from the network in a sentence: at most 80 bytes, control characters as '?'.
std::string shown_url(std::string_view url) {
    std::string out(url.substr(0, 80));
    std::replace_if(
        out.begin(), out.end(),
        [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }, '?');
    return out + (url.size() > 80 ? "..." : "");
}

SessionAction act(SessionActionKind kind) {
    return SessionAction{kind, 0.0, GiveUpReason::NoRetry};
}

} // namespace

SessionCore::SessionCore(BackoffSettings backoff, ReconnectPolicy policy, std::string address)
    : backoff_(backoff), policy_(policy), address_(std::move(address)), url_(address_) {}

SessionActions SessionCore::start(const std::string& resume_token) {
    if (!resume_token.empty()) {
        token_ = resume_token;
    }
    resuming_ = !resume_token.empty();
    ever_welcomed_ = false;
    waiting_ = false;
    end_loss();
    back_in_room_or_lobby();
    url_ = address_;
    redirect_close_due_ = false;
    retry_next_loss_ = false;
    phase_ = SessionPhase::Connecting;
    link_up_ = true;
    return {act(SessionActionKind::Connect)};
}

SessionActions SessionCore::request() {
    wants_room_ = true;
    if (phase_ != SessionPhase::Lobby) {
        return {}; // sent once welcomed
    }
    phase_ = SessionPhase::Joining;
    return {act(SessionActionKind::SendRoomRequest)};
}

SessionActions SessionCore::leave() {
    wants_room_ = false;
    back_in_room_or_lobby();
    resuming_ = false; // a reconnect says hello as a new player, without the old seat
    if (phase_ != SessionPhase::InRoom && phase_ != SessionPhase::Joining) {
        return {};
    }
    phase_ = SessionPhase::Lobby;
    return {act(SessionActionKind::SendLeave)};
}

SessionActions SessionCore::link_opened() {
    if (!link_up_ || (phase_ != SessionPhase::Connecting && phase_ != SessionPhase::Reconnecting)) {
        return {};
    }
    phase_ = SessionPhase::Greeting;
    return {act(resuming_ ? SessionActionKind::SendResume : SessionActionKind::SendHello)};
}

SessionActions SessionCore::link_closed(double now_s, int close_code, double jitter) {
    if (!link_up_ || phase_ == SessionPhase::Failed) {
        return {};
    }
    if (close_code == proto::kCloseRedirected && redirect_close_due_) {
        redirect_close_due_ = false; // the link the redirect left; the new one is up
        return {};
    }
    link_up_ = false;
    redirect_close_due_ = false;
    url_ = address_;
    redirects_ = 0;
    const bool retry_anyway = std::exchange(retry_next_loss_, false);
    if (close_code == proto::kCloseVersionMismatch) {
        return give_up(GiveUpReason::VersionMismatch);
    }
    if (close_code == proto::kCloseReplaced) {
        return give_up(GiveUpReason::Replaced);
    }
    const bool holds_seat = phase_ == SessionPhase::InRoom || resuming_;
    if (policy_ == ReconnectPolicy::Never ||
        (policy_ == ReconnectPolicy::SeatOnly && !holds_seat && !retry_anyway)) {
        return give_up(GiveUpReason::NoRetry);
    }
    if (tries_ == 0) {
        lost_since_s_ = now_s;
    }
    if (now_s - lost_since_s_ >= backoff_.give_up_after_s) {
        return give_up(GiveUpReason::TimeUp); // tries_: the tries made
    }
    ++tries_;
    resuming_ = holds_seat && !token_.empty();
    double nominal = backoff_.first_s;
    for (int n = 1; n < tries_ && nominal < backoff_.cap_s; ++n) {
        nominal *= 2.0;
    }
    nominal = std::min(nominal, backoff_.cap_s);
    const double drawn = nominal * (0.5 + 0.5 * std::clamp(jitter, 0.0, 1.0));
    const double wait_s = std::min(drawn, gives_up_at_s() - now_s);
    retry_at_s_ = now_s + wait_s;
    waiting_ = true;
    phase_ = ever_welcomed_ ? SessionPhase::Reconnecting : SessionPhase::Connecting;
    return {SessionAction{SessionActionKind::Wait, wait_s, GiveUpReason::NoRetry}};
}

SessionActions SessionCore::tick(double now_s) {
    if (!waiting_ || now_s < retry_at_s_) {
        return {};
    }
    waiting_ = false;
    link_up_ = true;
    return {act(SessionActionKind::Connect)};
}

SessionActions SessionCore::welcome(const std::string& token) {
    if (phase_ == SessionPhase::Failed) {
        return {};
    }
    ever_welcomed_ = true;
    redirect_close_due_ = false;
    if (resuming_) {
        if (token != token_) { // a new player: the seat is not ours any more
            token_ = token;
            if (!join_code_.empty()) { // a redirect named the room: join it instead
                resuming_ = false;
                phase_ = SessionPhase::Joining;
                return {act(SessionActionKind::SendJoin)};
            }
            return give_up_seat();
        }
        phase_ = SessionPhase::Joining; // the server sends the room back
        return {};
    }
    token_ = token;
    end_loss();
    phase_ = SessionPhase::Lobby;
    if (!wants_room_) {
        back_in_room_or_lobby();
        return {};
    }
    phase_ = SessionPhase::Joining;
    return {
        act(join_code_.empty() ? SessionActionKind::SendRoomRequest : SessionActionKind::SendJoin)};
}

SessionActions SessionCore::room_state() {
    if (phase_ != SessionPhase::Joining && phase_ != SessionPhase::InRoom) {
        return {}; // in the lobby: from a room we left; before a welcome: not ours
    }
    phase_ = SessionPhase::InRoom;
    wants_room_ = false;
    end_loss();
    back_in_room_or_lobby();
    if (!resuming_) {
        return {};
    }
    resuming_ = false;
    return {act(SessionActionKind::Resumed)};
}

SessionActions SessionCore::error(std::string_view code) {
    if (phase_ == SessionPhase::Failed) {
        return {};
    }
    if (code == proto::code::kVersionMismatch) {
        return give_up(GiveUpReason::VersionMismatch);
    }
    if (code == proto::code::kReplaced) {
        return give_up(GiveUpReason::Replaced);
    }
    if (code == proto::code::kBadToken && resuming_) {
        token_.clear();
        if (!join_code_.empty()) { // a redirect named the room: the welcome that follows joins it
            resuming_ = false;
            return {};
        }
        return give_up_seat();
    }
    if (code == proto::code::kMatchMoving) {
        retry_next_loss_ = true; // the close 1013 that follows is tried again
        return {};
    }
    if (phase_ == SessionPhase::Joining && !resuming_ && refuses_request(code)) {
        wants_room_ = false;
        back_in_room_or_lobby();
        phase_ = SessionPhase::Lobby;
        return {act(SessionActionKind::Refused)};
    }
    return {};
}

SessionActions SessionCore::redirect(const proto::Redirect& message) {
    const bool greeted = phase_ == SessionPhase::Greeting || phase_ == SessionPhase::Lobby ||
                         phase_ == SessionPhase::Joining || phase_ == SessionPhase::InRoom;
    if (!link_up_ || !greeted) {
        return {};
    }
    if (!redirect_allowed(url_, address_, message.url)) {
        refused_redirect_ = "redirect refused: " + shown_url(message.url) +
                            " is not an address of this cluster (" + shown_url(address_) + ").";
        return give_up(GiveUpReason::RedirectRefused);
    }
    if (redirects_ >= kMaxRedirects) {
        refused_redirect_ = "redirect refused: more than " + std::to_string(kMaxRedirects) +
                            " redirects in a row, the last to " + shown_url(message.url) + ".";
        return give_up(GiveUpReason::RedirectRefused);
    }
    ++redirects_;
    // A spectator holds no seat: it joins the named room again, without its token.
    const bool watching = !message.code.empty() && message.as == proto::Role::Spectator;
    resuming_ = (phase_ == SessionPhase::InRoom || resuming_) && !token_.empty() && !watching;
    if (!message.code.empty()) {
        join_code_ = message.code;
        join_as_ = message.as;
        wants_room_ = true;
    }
    url_ = message.url;
    redirect_close_due_ = true;
    phase_ = ever_welcomed_ ? SessionPhase::Reconnecting : SessionPhase::Connecting;
    return {act(SessionActionKind::Connect)};
}

SessionActions SessionCore::give_up_seat() {
    resuming_ = false;
    wants_room_ = false;
    back_in_room_or_lobby();
    end_loss();
    phase_ = SessionPhase::Lobby;
    return {act(SessionActionKind::SeatLost)};
}

SessionActions SessionCore::give_up(GiveUpReason reason) {
    phase_ = SessionPhase::Failed;
    link_up_ = false;
    waiting_ = false;
    resuming_ = false;
    return {SessionAction{SessionActionKind::GiveUp, 0.0, reason}};
}

void SessionCore::end_loss() {
    tries_ = 0;
}

void SessionCore::back_in_room_or_lobby() {
    redirects_ = 0;
    join_code_.clear();
    join_as_ = proto::Role::Player;
}

namespace {
constexpr enum_names::Table<SessionPhase, 7> kSessionPhaseNames{{
    {SessionPhase::Connecting, "connecting"},
    {SessionPhase::Greeting, "greeting"},
    {SessionPhase::Lobby, "lobby"},
    {SessionPhase::Joining, "joining"},
    {SessionPhase::InRoom, "in_room"},
    {SessionPhase::Reconnecting, "reconnecting"},
    {SessionPhase::Failed, "failed"},
}};

constexpr enum_names::Table<SessionActionKind, 11> kSessionActionNames{{
    {SessionActionKind::Connect, "connect"},
    {SessionActionKind::SendHello, "send_hello"},
    {SessionActionKind::SendResume, "send_resume"},
    {SessionActionKind::SendRoomRequest, "send_room_request"},
    {SessionActionKind::SendJoin, "send_join"},
    {SessionActionKind::SendLeave, "send_leave"},
    {SessionActionKind::Wait, "wait"},
    {SessionActionKind::Resumed, "resumed"},
    {SessionActionKind::SeatLost, "seat_lost"},
    {SessionActionKind::Refused, "refused"},
    {SessionActionKind::GiveUp, "give_up"},
}};

constexpr enum_names::Table<GiveUpReason, 5> kGiveUpReasonNames{{
    {GiveUpReason::NoRetry, "no_retry"},
    {GiveUpReason::TimeUp, "time_up"},
    {GiveUpReason::VersionMismatch, "version_mismatch"},
    {GiveUpReason::Replaced, "replaced"},
    {GiveUpReason::RedirectRefused, "redirect_refused"},
}};
} // namespace

std::string_view session_phase_name(SessionPhase phase) {
    return enum_names::name_or_unknown(kSessionPhaseNames, phase);
}

std::string_view session_action_name(SessionActionKind kind) {
    return enum_names::name_or_unknown(kSessionActionNames, kind);
}

std::string_view give_up_reason_name(GiveUpReason reason) {
    return enum_names::name_or_unknown(kGiveUpReasonNames, reason);
}

} // namespace carrom::net
