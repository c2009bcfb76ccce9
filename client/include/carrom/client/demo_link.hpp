#pragma once
// An offline stand-in for the server, behind the same MessageLink as the network: a real
// room::Room (the server's own room logic: rules, exact engine, shot streaming, shot results,
// shot clock) driven in this process, with the player as a local peer and the demo opponent
// (DemoOpponent) in a bot seat. The link answers hello and ping itself, as a server session
// does; everything else goes to the room, and everything the room sends passes through the
// wire codec. The player takes seat 0; the opponent breaks the first game. Used by
// `carrom-client --demo`, the frame benchmark and the screenshot test; nothing leaves the process.

#include "carrom/client/connection.hpp"
#include "carrom/client/demo_opponent.hpp"
#include "carrom/config.hpp"
#include "carrom/room/room.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace carrom::client {

struct DemoConfig {
    double first_shot_at_s = 1.5;  // the opponent breaks this long after the room opens
    double opponent_think_s = 1.5; // the opponent's time per later stroke
    double autoplay_after_s = -1;  // if >= 0, the player's shot is played for them after this
    double snapshot_hz = 60.0;
    std::int64_t server_clock_offset_ms = 1'234'567; // the demo server's clock is not ours
    double shot_clock_s = 30.0;
};

class DemoLink final : public MessageLink {
public:
    // clock() gives the local time in s; the room reads it (plus the offset) as its clock.
    DemoLink(const PhysicsConfig& physics, std::function<double()> clock,
             const DemoConfig& config = {});
    ~DemoLink() override;
    DemoLink(const DemoLink&) = delete;
    DemoLink& operator=(const DemoLink&) = delete;

    void send(const proto::ClientMessage& message) override;
    std::vector<proto::ServerMessage> poll() override;
    LinkStatus status() const override;
    void close() override;

private:
    class LocalClock;
    class LocalPeer;

    void open_room(proto::RuleSet rule_set, const proto::RoomOptions& options, double now_s);
    void answer(const proto::ServerMessage& message);
    // Time-driven work: the room's tick, then the opponent's and the autoplayed strokes.
    void advance(double now_s);
    void note_turn(double now_s);

    PhysicsConfig physics_;
    DemoConfig config_;
    std::unique_ptr<LocalClock> clock_;
    room::RoomCounters counters_;
    std::shared_ptr<LocalPeer> peer_;
    std::shared_ptr<DemoOpponent> opponent_ = std::make_shared<DemoOpponent>();
    std::unique_ptr<room::Room> room_;
    bool open_ = true;
    bool first_break_ = true;               // the opponent's first stroke waits first_shot_at_s
    int turn_seen_ = -1;                    // the turn the room last showed at rest
    double turn_seen_at_s_ = 0.0;           // local time it was first seen
    std::optional<room::BotTurn> bot_turn_; // handed out by the room, not played yet
};

} // namespace carrom::client
