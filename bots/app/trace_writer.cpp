#include "trace_writer.hpp"

#include <nlohmann/json.hpp>

#include <chrono>

namespace carrom::bots {

std::optional<std::string> TraceWriter::open(const std::string& path) {
    out_.open(path, std::ios::out | std::ios::trunc);
    if (!out_) {
        return "--trace: cannot write " + path;
    }
    return std::nullopt;
}

double TraceWriter::now_ms() {
    const auto since = std::chrono::steady_clock::now().time_since_epoch();
    return std::chrono::duration<double, std::milli>(since).count();
}

void TraceWriter::shoot(const proto::Shoot& shoot) {
    if (!out_.is_open()) {
        return;
    }
    const nlohmann::json line{{"ms", now_ms()},           {"kind", "shoot"},
                              {"turn", shoot.turn},       {"x", shoot.x_px},
                              {"angle", shoot.angle_rad}, {"power", shoot.power}};
    out_ << line.dump() << '\n' << std::flush;
}

void TraceWriter::message(const proto::ServerMessage& message) {
    if (!out_.is_open()) {
        return;
    }
    if (const auto* snapshot = std::get_if<proto::Snapshot>(&message)) {
        const nlohmann::json line{{"ms", now_ms()},
                                  {"kind", "snapshot"},
                                  {"turn", snapshot->turn},
                                  {"seq", snapshot->seq},
                                  {"t", snapshot->t_s},
                                  {"keyframe", snapshot->keyframe},
                                  {"bodies", snapshot->bodies.size()}};
        out_ << line.dump() << '\n' << std::flush;
    } else if (const auto* room = std::get_if<proto::RoomState>(&message)) {
        const nlohmann::json line{{"ms", now_ms()},
                                  {"kind", "room_state"},
                                  {"turn", room->turn},
                                  {"phase", proto::to_string(room->phase)}};
        out_ << line.dump() << '\n' << std::flush;
    }
}

void TraceWriter::notice(const std::string& text) {
    if (!out_.is_open()) {
        return;
    }
    const nlohmann::json line{{"ms", now_ms()}, {"kind", "notice"}, {"text", text}};
    out_ << line.dump() << '\n' << std::flush;
}

} // namespace carrom::bots
