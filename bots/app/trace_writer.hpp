#pragma once
// carrom-bot --trace FILE: one JSON object per line for each shot sent, each snapshot and
// room_state received, and each connection notice, stamped with the monotonic clock
// (CLOCK_MONOTONIC, ms). That clock is shared by every process on the machine, network
// namespaces included, so the traces of two bots line up: scripts/network_report.py measures
// from them how long after a shot leaves the shooter its motion reaches each player.

#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"

#include <fstream>
#include <optional>
#include <string>

namespace carrom::bots {

class TraceWriter {
public:
    // Opens (truncates) path; the error sentence when it cannot.
    std::optional<std::string> open(const std::string& path);
    bool is_open() const { return out_.is_open(); }

    // {"ms":..,"kind":"shoot","turn":..,"x":..,"angle":..,"power":..}
    void shoot(const proto::Shoot& shoot);
    // {"ms":..,"kind":"snapshot","turn":..,"seq":..,"t":..,"keyframe":..,"bodies":N} and
    // {"ms":..,"kind":"room_state","turn":..,"phase":".."}; other messages are not traced.
    void message(const proto::ServerMessage& message);
    // {"ms":..,"kind":"notice","text":".."}
    void notice(const std::string& text);

private:
    static double now_ms();
    std::ofstream out_;
};

} // namespace carrom::bots
