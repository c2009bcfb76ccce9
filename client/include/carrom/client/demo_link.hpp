#pragma once
// An offline stand-in for the server, behind the same MessageLink as the network: it answers
// hello and the room request, plays a match with the real rules and the exact engine, and
// streams every shot as the server does (deltas at the snapshot rate, physics events at their
// time, a keyframe at the end, then the shot result, the next turn and the room state). Seat 0 is
// the player; seat 1 is a demo opponent that breaks. Used by `carrom-client --demo`, the frame
// benchmark and the screenshot test; nothing leaves the process.

#include "carrom/client/connection.hpp"
#include "carrom/config.hpp"
#include "carrom/exact_engine.hpp"
#include "carrom/rules/match.hpp"

#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client {

struct DemoConfig {
    double first_shot_at_s = 1.5;  // the opponent breaks this long after the room opens
    double opponent_think_s = 1.5; // the opponent's time per shot
    double autoplay_after_s = -1;  // if >= 0, the player's shot is played for them after this
    double snapshot_hz = 60.0;
    std::int64_t server_clock_offset_ms = 1'234'567; // the demo server's clock is not ours
    double shot_clock_s = 30.0;
};

class DemoLink final : public MessageLink {
public:
    // clock() gives the local time in s; it is read on every send and poll.
    DemoLink(const PhysicsConfig& physics, std::function<double()> clock,
             const DemoConfig& config = {});

    void send(const proto::ClientMessage& message) override;
    std::vector<proto::ServerMessage> poll() override;
    LinkStatus status() const override;
    void close() override;

private:
    struct Streaming {
        double start_s = 0.0; // local time of t = 0
        int turn = 0;
        std::size_t next_event = 0;
        int next_frame = 0; // snapshot index; t = index / rate
        std::vector<Body> last_sent;
        rules::PlayResult play;
    };

    void advance(double now_s);
    void open_room(double now_s);
    void start_shot(int seat, const Shot& shot, double now_s);
    void stream(double now_s);
    void finish_shot(double now_s);
    Shot demo_shot(int seat) const;
    proto::RoomState room_state(double now_s) const;
    proto::TurnEvent turn_event(double now_s) const;
    std::int64_t server_ms(double now_s) const;

    PhysicsConfig physics_;
    std::function<double()> clock_;
    DemoConfig config_;
    ExactEngine engine_;
    bool open_ = true;
    std::string player_name_ = "Player";
    bool in_room_ = false;
    rules::MatchState match_;
    std::optional<Streaming> streaming_;
    double turn_started_s_ = 0.0;
    std::int64_t seq_ = 0;
    std::deque<proto::ServerMessage> outbox_;
};

} // namespace carrom::client
