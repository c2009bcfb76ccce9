// The "room" fuzz target: byte-driven sequences of the calls the network layer makes on a
// server Room (join, leave, disconnect, resume, aim, shoot, rematch, tick, playing a shot out)
// for four fake players, on a manual clock. Every value passed in is one decode_client could
// produce (aim and shot values may still be off the baseline or out of turn, as from a hostile
// client). Failures: a sanitizer report, an exception, a message sent to a peer that
// proto::decode_server rejects, a moving board with no wake-up time, or a shot still moving
// after 200000 ticks (fuzz::fail, which aborts).
//
// Input layout: byte 0 = rule set, byte 1 = option flags (then the options it selects), then
// one operation per byte: bits 6-7 = player 0..3, bits 0-3 = operation, bit 4 = spectator (join);
// aim and shoot read their values from the following bytes. Missing bytes read as zero.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/limits.hpp"
#include "carrom/room/room.hpp"
#include "fuzz.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <numbers>
#include <string>

namespace carrom::fuzz {
namespace {

using room::Peer;

// A player's connection: checks that every message the room sends it decodes.
class CheckingPeer final : public Peer {
public:
    CheckingPeer(std::int64_t id, std::string name) : id_(id), name_(std::move(name)) {}
    std::int64_t player_id() const override { return id_; }
    const std::string& name() const override { return name_; }
    void send(room::Outgoing message) override {
        const auto decoded = proto::decode_server(*message.text);
        if (!decoded.ok()) {
            fail("room: sent a message decode_server rejects (" + decoded.error.code + ": " +
                     decoded.error.message + ")",
                 *message.text);
        }
    }
    bool take_keyframe_request() override { return false; }
    void close(int, std::string) override {}

private:
    std::int64_t id_;
    std::string name_;
};

// The input, read front to back; zeros once it runs out.
class Bytes {
public:
    Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    bool done() const { return at_ >= size_; }
    std::uint8_t u8() { return at_ < size_ ? data_[at_++] : 0; }
    int u16() {
        const int low = u8();
        return low | (u8() << 8);
    }
    double unit() { return u16() / 65535.0; } // [0, 1]

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

constexpr int kMaxPlayOutTicks = 200000;

// Moves the clock to the room's next wake-up (never back) and ticks; false if none is set.
bool tick_at_next_wake(room::Room& room, room::ManualClock& clock) {
    const auto wake = room.next_wake_ms();
    if (!wake) {
        return false;
    }
    clock.set_ms(std::max(clock.now_ms(), *wake));
    room.tick();
    return true;
}

void play_out(room::Room& room, room::ManualClock& clock) {
    int ticks = 0;
    while (room.phase() == proto::Phase::Moving) {
        if (!tick_at_next_wake(room, clock)) {
            fail("room: the board is moving but next_wake_ms() is empty");
        }
        if (++ticks > kMaxPlayOutTicks) {
            fail("room: a shot is still moving after 200000 ticks");
        }
    }
}

} // namespace
} // namespace carrom::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace carrom;
    using fuzz::CheckingPeer;
    fuzz::Bytes in(data, size);
    room::ManualClock clock;
    room::RoomCounters counters;
    room::RoomConfig config;
    config.rule_set = static_cast<proto::RuleSet>(in.u8() % 4);
    proto::RoomOptions options;
    const std::uint8_t flags = in.u8();
    if (flags & 1) {
        options.target_points = 1 + in.u8() % 30;
    }
    if (flags & 2) {
        options.boards = 1 + in.u8() % 5;
    }
    if (flags & 4) {
        options.shot_clock_s = (flags & 8) ? 0.0 : 0.5 + in.unit() * 30.0;
    }
    config.rules = room::make_rules_config(config.rule_set, options, 30.0);
    config.grace_s = 1.0 + in.u8();
    config.time_scale = (flags & 16) ? 50.0 : 1.0;
    room::Room room("ABCDEF", config, clock, counters);

    std::array<std::shared_ptr<CheckingPeer>, 4> peers;
    for (std::size_t k = 0; k < peers.size(); ++k) {
        peers[k] = std::make_shared<CheckingPeer>(static_cast<std::int64_t>(k) + 1,
                                                  "p" + std::to_string(k));
    }
    while (!in.done()) {
        const std::uint8_t op = in.u8();
        std::shared_ptr<CheckingPeer>& slot = peers[op >> 6];
        CheckingPeer& peer = *slot;
        switch (op & 15) {
        case 0:
            (void)room.join(slot, (op & 16) ? proto::Role::Spectator : proto::Role::Player);
            break;
        case 1:
            room.leave(peer);
            break;
        case 2:
            room.disconnected(peer);
            break;
        case 3: // the same player on a new connection
            slot = std::make_shared<CheckingPeer>(peer.player_id(), peer.name());
            (void)room.resume(slot);
            break;
        case 4:
        case 5: {
            // Mostly plausible values (on the baseline, the current turn), sometimes anything
            // within the wire limits.
            const bool sane = (in.u8() & 3) != 0;
            const int turn =
                sane ? room.match().turn_number : in.u16() % static_cast<int>(proto::kMaxTurn + 1);
            const double x = sane ? 150.0 + 300.0 * in.unit() : proto::kMaxCoordinatePx * in.unit();
            if ((op & 15) == 4) {
                room.aim(peer, proto::Aim{turn, x});
                break;
            }
            const double angle = sane ? -std::numbers::pi * in.unit()
                                      : proto::kMaxAngleRad * (2.0 * in.unit() - 1.0);
            const double power = sane ? 25.0 * in.unit() : proto::kMaxPower * in.unit();
            room.shoot(peer, proto::Shoot{turn, x, angle, power});
            break;
        }
        case 6:
            room.rematch(peer);
            break;
        case 7:
            clock.advance_ms(in.u16());
            room.tick();
            break;
        case 8:
            fuzz::play_out(room, clock);
            break;
        default: // the next timed wake-up, if any
            (void)fuzz::tick_at_next_wake(room, clock);
            break;
        }
    }
    return 0;
}
