#include "carrom/client/client_session.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>

namespace carrom::client {
namespace {

// A link the test drives: it records what the client sends and delivers what the test queues.
struct FakeWire {
    std::string url; // where the session opened it
    LinkState state = LinkState::Connecting;
    std::string detail;
    int close_code = 0;
    std::vector<proto::ClientMessage> sent;
    std::deque<proto::ServerMessage> inbox;
};

class FakeLink final : public MessageLink {
public:
    explicit FakeLink(FakeWire& wire) : wire_(wire) {}
    void send(const proto::ClientMessage& m) override { wire_.sent.push_back(m); }
    std::vector<proto::ServerMessage> poll() override {
        std::vector<proto::ServerMessage> out(wire_.inbox.begin(), wire_.inbox.end());
        wire_.inbox.clear();
        return out;
    }
    LinkStatus status() const override { return {wire_.state, wire_.detail, wire_.close_code}; }
    void close() override {}

private:
    FakeWire& wire_;
};

const std::string kAddress = "ws://127.0.0.1:7777";

SessionConfig harness_config() {
    SessionConfig config;
    config.address = kAddress;
    return config;
}

struct Harness {
    std::vector<std::unique_ptr<FakeWire>> wires;
    ClientSession session{[this](const std::string& url) {
                              wires.push_back(std::make_unique<FakeWire>());
                              wires.back()->url = url;
                              return std::make_unique<FakeLink>(*wires.back());
                          },
                          "Ana", harness_config()};
    FakeWire& wire() { return *wires.back(); }
    // Asks to create a room, connects and is in the room (welcomed with kToken) by 0.2 s.
    void into_room();
    // Asks for a quick match, connects and is welcomed (kToken) and waiting by 0.2 s.
    void into_quick_match_queue();
};

const std::string kToken = "0123456789abcdef0123456789abcdef";

void Harness::into_room() {
    session.request({RoomRequest::Kind::Create, "", proto::RuleSet::Icf, std::nullopt});
    session.start(0.0);
    wire().state = LinkState::Open;
    session.update(0.1);
    wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    wire().inbox.push_back(proto::RoomState{});
    session.update(0.2);
}

void Harness::into_quick_match_queue() {
    session.request({RoomRequest::Kind::Quick, "", proto::RuleSet::Icf, std::nullopt});
    session.start(0.0);
    wire().state = LinkState::Open;
    session.update(0.1);
    wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    session.update(0.2);
}

template <class T> bool has_sent(const FakeWire& w) {
    return std::any_of(w.sent.begin(), w.sent.end(),
                       [](const proto::ClientMessage& m) { return std::holds_alternative<T>(m); });
}

// The last message of type T sent on the wire (a default one if none was).
template <class T> T sent(const FakeWire& w) {
    T out{};
    for (const proto::ClientMessage& m : w.sent) {
        if (std::holds_alternative<T>(m)) {
            out = std::get<T>(m);
        }
    }
    return out;
}

TEST(ClientSession, HelloThenTheRoomRequest) {
    Harness h;
    h.session.request({RoomRequest::Kind::Join, "ABC234", proto::RuleSet::Icf, std::nullopt});
    h.session.start(0.0);
    EXPECT_EQ(h.session.phase(), SessionPhase::Connecting);
    h.session.update(0.1);
    EXPECT_TRUE(h.wire().sent.empty()); // not open yet
    h.wire().state = LinkState::Open;
    h.session.update(0.2);
    ASSERT_TRUE(has_sent<proto::Hello>(h.wire()));
    EXPECT_EQ(sent<proto::Hello>(h.wire()).name, "Ana");
    EXPECT_EQ(sent<proto::Hello>(h.wire()).resume_token, std::nullopt);
    EXPECT_EQ(h.session.phase(), SessionPhase::Greeting);
    h.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    const auto out = h.session.update(0.3);
    EXPECT_EQ(out.size(), 1u); // the welcome goes on to the match model
    ASSERT_TRUE(has_sent<proto::JoinRoom>(h.wire()));
    EXPECT_EQ(sent<proto::JoinRoom>(h.wire()).code, "ABC234");
    EXPECT_EQ(h.session.phase(), SessionPhase::Joining);
    h.wire().inbox.push_back(proto::RoomState{});
    h.session.update(0.4);
    EXPECT_EQ(h.session.phase(), SessionPhase::InRoom);
    EXPECT_EQ(h.session.resume_token(), kToken);
}

TEST(ClientSession, RefusedRoomRequestsGoBackToTheLobby) {
    for (const std::string_view code :
         {proto::code::kUnsupported, proto::code::kRoomNotFound, proto::code::kRoomFull,
          proto::code::kTooManyRooms, proto::code::kBadField}) {
        Harness h;
        h.session.request({RoomRequest::Kind::Create, "", proto::RuleSet::Icf,
                           proto::BotSeat{proto::BotLevel::Easy}});
        h.session.start(0.0);
        h.wire().state = LinkState::Open;
        h.session.update(0.1);
        h.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
        h.session.update(0.2);
        ASSERT_TRUE(has_sent<proto::CreateRoom>(h.wire()));
        EXPECT_EQ(sent<proto::CreateRoom>(h.wire()).bot, proto::BotSeat{proto::BotLevel::Easy});
        EXPECT_EQ(h.session.phase(), SessionPhase::Joining);
        h.wire().inbox.push_back(proto::Error{std::string(code), "No."});
        const auto out = h.session.update(0.3);
        EXPECT_EQ(out.size(), 1u) << code; // the error goes on to be shown
        EXPECT_EQ(h.session.phase(), SessionPhase::Lobby) << code;
    }
    Harness other; // an error that is no answer to the request keeps waiting for the room
    other.session.request({RoomRequest::Kind::Join, "ABC234", proto::RuleSet::Icf, std::nullopt});
    other.session.start(0.0);
    other.wire().state = LinkState::Open;
    other.session.update(0.1);
    other.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    other.session.update(0.2);
    other.wire().inbox.push_back(proto::Error{std::string(proto::code::kRateLimited), "Slow."});
    other.session.update(0.3);
    EXPECT_EQ(other.session.phase(), SessionPhase::Joining);
}

TEST(ClientSession, LobbyWaitsForAChoice) {
    Harness h;
    h.session.start(0.0);
    h.wire().state = LinkState::Open;
    h.session.update(0.1);
    h.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    h.session.update(0.2);
    EXPECT_EQ(h.session.phase(), SessionPhase::Lobby);
    EXPECT_FALSE(has_sent<proto::CreateRoom>(h.wire()));
    h.session.request({RoomRequest::Kind::Quick, "", proto::RuleSet::Freestyle, std::nullopt});
    ASSERT_TRUE(has_sent<proto::QuickMatch>(h.wire()));
    EXPECT_EQ(sent<proto::QuickMatch>(h.wire()).rule_set, proto::RuleSet::Freestyle);
}

TEST(ClientSession, GameInputOnlyInARoom) {
    Harness h;
    h.session.request({RoomRequest::Kind::Join, "ABC234", proto::RuleSet::Icf, std::nullopt});
    h.session.start(0.0);
    EXPECT_FALSE(h.session.send_game(proto::Shoot{}));
    h.wire().state = LinkState::Open;
    h.session.update(0.1);
    h.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    h.wire().inbox.push_back(proto::RoomState{});
    h.session.update(0.2);
    EXPECT_TRUE(h.session.send_game(proto::Shoot{3, 300.0, -1.5, 20.0}));
    EXPECT_EQ(sent<proto::Shoot>(h.wire()).turn, 3);
}

TEST(ClientSession, ADropReconnectsAndResumesWithTheToken) {
    Harness h;
    h.into_room();
    ASSERT_EQ(h.session.phase(), SessionPhase::InRoom);
    h.wire().state = LinkState::Closed;
    h.wire().detail = "Connection reset by peer";
    h.session.update(1.0);
    EXPECT_EQ(h.session.phase(), SessionPhase::Reconnecting);
    EXPECT_NE(h.session.status_text().find("Connection reset by peer"), std::string::npos);
    EXPECT_EQ(h.wires.size(), 1u);
    h.session.update(1.2); // back-off: 0.5 s
    EXPECT_EQ(h.wires.size(), 1u);
    h.session.update(1.6);
    ASSERT_EQ(h.wires.size(), 2u);
    h.wire().state = LinkState::Open;
    h.session.update(1.7);
    ASSERT_TRUE(has_sent<proto::Hello>(h.wire()));
    EXPECT_EQ(sent<proto::Hello>(h.wire()).resume_token, kToken);
    h.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 2000});
    h.session.update(1.8);
    // Resuming asks for no room: the server sends ours back.
    EXPECT_FALSE(has_sent<proto::CreateRoom>(h.wire()));
    h.wire().inbox.push_back(proto::RoomState{});
    h.session.update(1.9);
    EXPECT_EQ(h.session.phase(), SessionPhase::InRoom);
}

TEST(ClientSession, ASeatOpenedOnAnotherLinkIsNotTakenBack) {
    Harness h;
    h.into_room();
    h.wire().state = LinkState::Closed;
    h.wire().detail = "The server closed the connection (code 4002: replaced).";
    h.wire().close_code = 4002;
    h.session.update(0.3);
    EXPECT_EQ(h.session.phase(), SessionPhase::Failed);
    h.session.update(30.0);
    EXPECT_EQ(h.wires.size(), 1u); // no new link
}

TEST(ClientSession, ARequestLostBeforeItsAnswerIsAskedAgainByANewPlayer) {
    Harness h;
    h.into_quick_match_queue();
    ASSERT_TRUE(has_sent<proto::QuickMatch>(h.wire()));
    h.wire().state = LinkState::Closed; // still in the queue: no seat to resume
    h.session.update(20.0);
    h.session.update(20.5);
    ASSERT_EQ(h.wires.size(), 2u);
    h.wire().state = LinkState::Open;
    h.session.update(20.6);
    EXPECT_EQ(sent<proto::Hello>(h.wire()).resume_token, std::nullopt);
    h.wire().inbox.push_back(proto::Welcome{1, 8, std::string(32, 'b'), 2000});
    h.session.update(20.7);
    EXPECT_TRUE(has_sent<proto::QuickMatch>(h.wire()));
    EXPECT_EQ(h.session.phase(), SessionPhase::Joining);
}

TEST(ClientSession, LostLinkReasonReadsAsOneSentence) {
    for (const std::string& detail :
         {std::string("Could not reach 127.0.0.1:9: connection refused."),
          std::string("Could not reach 127.0.0.1:9: connection refused")}) {
        Harness h;
        h.session.start(0.0);
        h.wire().state = LinkState::Closed;
        h.wire().detail = detail;
        h.session.update(0.1);
        EXPECT_EQ(h.session.status_text(),
                  "Could not reach 127.0.0.1:9: connection refused. Retrying in 0.5 s (attempt 1)")
            << detail;
    }
    Harness quiet; // a link that closes without a reason
    quiet.session.start(0.0);
    quiet.wire().state = LinkState::Closed;
    quiet.session.update(0.1);
    EXPECT_EQ(quiet.session.status_text(),
              "The connection was lost. Retrying in 0.5 s (attempt 1)");
}

TEST(ClientSession, BackOffDoublesAndGivesUp) {
    Harness h;
    h.session.start(0.0);
    double now = 0.0;
    std::vector<double> opened_at;
    for (int i = 0; i < 3000 && h.session.phase() != SessionPhase::Failed; ++i) {
        const std::size_t before = h.wires.size();
        h.wire().state = LinkState::Closed;
        h.wire().detail = "Could not reach 127.0.0.1:9: connection refused";
        h.session.update(now);
        if (h.wires.size() != before) {
            opened_at.push_back(now);
        }
        now += 0.05;
    }
    EXPECT_EQ(h.session.phase(), SessionPhase::Failed);
    EXPECT_NE(h.session.status_text().find("connection refused"), std::string::npos);
    ASSERT_GE(opened_at.size(), 4u);
    EXPECT_NEAR(opened_at[1] - opened_at[0], 1.0, 0.12); // 0.5, 1, 2, 4, 5, 5, ...
    EXPECT_NEAR(opened_at[2] - opened_at[1], 2.0, 0.12);
    EXPECT_GE(now, 130.0);
}

TEST(ClientSession, JitterDrawsEachDelayInItsUpperHalfAndReportsTheTries) {
    std::vector<std::unique_ptr<FakeWire>> wires;
    SessionConfig config;
    config.jitter_seed = 5;
    ClientSession session(
        [&wires](const std::string&) {
            wires.push_back(std::make_unique<FakeWire>());
            return std::make_unique<FakeLink>(*wires.back());
        },
        "Ana", config);
    session.start(0.0);
    double now = 0.0;
    std::vector<double> opened_at{0.0};
    while (opened_at.size() < 5) {
        const std::size_t before = wires.size();
        wires.back()->state = LinkState::Closed;
        session.update(now);
        if (wires.size() != before) {
            opened_at.push_back(now);
        }
        now += 0.01;
    }
    // Nominal 0.5, 1, 2, 4 s; each drawn in [d/2, d] (plus the 10 ms polling step).
    const double nominal[] = {0.5, 1.0, 2.0, 4.0};
    bool below = false;
    for (int i = 0; i < 4; ++i) {
        const double waited =
            opened_at[static_cast<std::size_t>(i) + 1] - opened_at[static_cast<std::size_t>(i)];
        EXPECT_GE(waited, nominal[i] / 2.0 - 0.011) << i;
        EXPECT_LE(waited, nominal[i] + 0.02) << i;
        below = below || waited < nominal[i] - 0.05;
    }
    EXPECT_TRUE(below); // not all at the nominal delay
    const ReconnectInfo info = session.reconnect_info(now);
    EXPECT_EQ(info.attempt, 4);
    EXPECT_TRUE(info.trying);
    EXPECT_EQ(info.reason, "The connection was lost.");
    EXPECT_NEAR(info.gives_up_in_s, 130.0 - now, 1e-9);
}

TEST(ClientSession, LostSeatGoesBackToTheLobby) {
    Harness h;
    h.into_room();
    h.wire().state = LinkState::Closed;
    h.session.update(0.3);
    h.session.update(1.0);
    h.wire().state = LinkState::Open;
    h.session.update(1.1);
    h.wire().inbox.push_back(proto::Error{"bad_token", "Unknown token."});
    const auto out = h.session.update(1.2);
    EXPECT_EQ(out.size(), 1u); // the error is shown by the match model
    EXPECT_EQ(h.session.phase(), SessionPhase::Lobby);
    EXPECT_TRUE(h.session.seat_lost());
}

TEST(ClientSession, LeavingTheRoomGoesBackToTheLobbyOnTheSameLink) {
    Harness h;
    h.into_room();
    ASSERT_EQ(h.session.phase(), SessionPhase::InRoom);
    h.session.leave_room();
    EXPECT_TRUE(has_sent<proto::Leave>(h.wire()));
    EXPECT_EQ(h.session.phase(), SessionPhase::Lobby);
    EXPECT_EQ(h.wires.size(), 1u);
    EXPECT_FALSE(h.session.send_game(proto::Rematch{}));
    // What the room sent before the server had our leave is dropped; errors still come through.
    proto::RoomState late;
    late.code = "ABC234";
    h.wire().inbox.push_back(late);
    h.wire().inbox.push_back(proto::Event{proto::PlayerReturnedEvent{1}});
    h.wire().inbox.push_back(proto::Error{"rate_limited", "Slow."});
    const auto out = h.session.update(0.3);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(std::holds_alternative<proto::Error>(out[0]));
    EXPECT_EQ(h.session.phase(), SessionPhase::Lobby);
    // The lobby's next choice is sent at once, and its room comes through.
    h.session.request({RoomRequest::Kind::Join, "XYZ789", proto::RuleSet::Icf, std::nullopt});
    EXPECT_EQ(sent<proto::JoinRoom>(h.wire()).code, "XYZ789");
    h.wire().inbox.push_back(proto::RoomState{});
    EXPECT_EQ(h.session.update(0.4).size(), 1u);
    EXPECT_EQ(h.session.phase(), SessionPhase::InRoom);
}

TEST(ClientSession, VersionMismatchFails) {
    Harness h;
    h.session.start(0.0);
    h.wire().state = LinkState::Open;
    h.session.update(0.1);
    h.wire().inbox.push_back(proto::Error{"version_mismatch", "Protocol 2 required."});
    h.session.update(0.2);
    EXPECT_EQ(h.session.phase(), SessionPhase::Failed);
}

TEST(ClientSession, EveryHelloFollowsRedirects) {
    Harness h;
    h.into_room();
    EXPECT_EQ(h.wire().url, kAddress);
    EXPECT_TRUE(sent<proto::Hello>(h.wire()).follows_redirects);
    h.wire().state = LinkState::Closed;
    h.session.update(1.0);
    h.session.update(1.5);
    h.wire().state = LinkState::Open;
    h.session.update(1.6);
    EXPECT_EQ(sent<proto::Hello>(h.wire()).resume_token, kToken);
    EXPECT_TRUE(sent<proto::Hello>(h.wire()).follows_redirects);
}

TEST(ClientSession, ARedirectConnectsThereAndJoinsTheNamedRoom) {
    Harness h;
    h.into_quick_match_queue();
    ASSERT_TRUE(has_sent<proto::QuickMatch>(h.wire()));
    h.wire().inbox.push_back(
        proto::Redirect{"ws://127.0.0.1:7801/i/b/", "quick_match", "K7M2QX", proto::Role::Player});
    h.wire().inbox.push_back(proto::Pong{1, 1}); // the old link's: not read
    EXPECT_TRUE(h.session.update(3.0).empty());
    ASSERT_EQ(h.wires.size(), 2u);
    EXPECT_EQ(h.wire().url, "ws://127.0.0.1:7801/i/b/");
    h.wire().state = LinkState::Open;
    h.session.update(3.1);
    EXPECT_FALSE(sent<proto::Hello>(h.wire()).resume_token.has_value());
    EXPECT_TRUE(sent<proto::Hello>(h.wire()).follows_redirects);
    h.wire().inbox.push_back(proto::Welcome{1, 8, kToken, 1000});
    h.session.update(3.2);
    EXPECT_EQ(sent<proto::JoinRoom>(h.wire()), (proto::JoinRoom{"K7M2QX", proto::Role::Player}));
    EXPECT_FALSE(has_sent<proto::QuickMatch>(h.wire()));
    h.wire().inbox.push_back(proto::RoomState{});
    h.session.update(3.3);
    EXPECT_EQ(h.session.phase(), SessionPhase::InRoom);
    EXPECT_EQ(h.wires.size(), 2u);
}

// A room handed over while it waited for its players keeps no seat: the resume's bad_token is
// the session's business (it joins the named room), not a message for the player.
TEST(ClientSession, AMovedRoomWithoutASeatToResumeIsJoinedWithoutAnErrorShown) {
    Harness h;
    h.into_room();
    h.wire().inbox.push_back(
        proto::Redirect{"ws://127.0.0.1:7801/i/b/", "moved", "K7M2QX", proto::Role::Player});
    h.session.update(1.0);
    ASSERT_EQ(h.wires.size(), 2u);
    h.wire().state = LinkState::Open;
    h.session.update(1.1);
    EXPECT_EQ(sent<proto::Hello>(h.wire()).resume_token, kToken);
    h.wire().inbox.push_back(proto::Error{"bad_token", "That resume token is unknown."});
    h.wire().inbox.push_back(proto::Welcome{1, 8, std::string(32, 'e'), 1000});
    const auto out = h.session.update(1.2);
    for (const auto& m : out) {
        EXPECT_FALSE(std::holds_alternative<proto::Error>(m));
    }
    EXPECT_EQ(sent<proto::JoinRoom>(h.wire()), (proto::JoinRoom{"K7M2QX", proto::Role::Player}));
    h.wire().inbox.push_back(proto::RoomState{});
    h.session.update(1.3);
    EXPECT_EQ(h.session.phase(), SessionPhase::InRoom);
}

TEST(ClientSession, ARedirectToAnotherHostIsRefusedAndNeverConnected) {
    Harness h;
    h.into_room();
    h.wire().inbox.push_back(
        proto::Redirect{"ws://127.0.0.2:7777/", "moved", "K7M2QX", proto::Role::Player});
    h.session.update(1.0);
    EXPECT_EQ(h.wires.size(), 1u);
    EXPECT_EQ(h.session.phase(), SessionPhase::Failed);
    EXPECT_EQ(h.session.status_text(), "redirect refused: ws://127.0.0.2:7777/ is not an address "
                                       "of this cluster (ws://127.0.0.1:7777).");
    h.session.update(10.0);
    EXPECT_EQ(h.wires.size(), 1u);
}

TEST(ClientSession, PingsMeasureTheRoundTrip) {
    Harness h;
    h.session.start(0.0);
    h.wire().state = LinkState::Open;
    h.session.update(0.0);
    h.wire().inbox.push_back(proto::Welcome{1, 7, kToken, 1000});
    h.session.update(0.1);
    ASSERT_TRUE(has_sent<proto::Ping>(h.wire()));
    h.wire().inbox.push_back(proto::Pong{sent<proto::Ping>(h.wire()).nonce, 123456});
    const auto out = h.session.update(0.18);
    EXPECT_TRUE(out.empty()); // pongs stay in the session
    ASSERT_TRUE(h.session.rtt_ms().has_value());
    EXPECT_NEAR(*h.session.rtt_ms(), 80.0, 1e-9);
    const auto pongs = h.session.take_pongs();
    ASSERT_EQ(pongs.size(), 1u);
    EXPECT_EQ(pongs[0].server_ms, 123456);
    // An unknown nonce is ignored.
    h.wire().inbox.push_back(proto::Pong{999, 1});
    h.session.update(0.2);
    EXPECT_TRUE(h.session.take_pongs().empty());
}

} // namespace
} // namespace carrom::client
