#include "carrom/room/snapshot_writer.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

namespace carrom::room {

namespace {

void append_int(std::string& out, std::int64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

// Shortest round-trip form; JSON has no NaN or infinity (the engine never produces them, but a
// valid message matters more than the value).
void append_number(std::string& out, double value) {
    if (!std::isfinite(value)) {
        value = 0.0;
    }
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

} // namespace

std::string encode_snapshot(const proto::Snapshot& s) {
    std::string out;
    out.reserve(96 + s.bodies.size() * 48 + s.pocketed.size() * 4);
    out += R"({"type":"snapshot","seq":)";
    append_int(out, s.seq);
    out += R"(,"turn":)";
    append_int(out, s.turn);
    out += R"(,"t":)";
    append_number(out, s.t_s);
    out += s.keyframe ? R"(,"keyframe":true,"bodies":[)" : R"(,"keyframe":false,"bodies":[)";
    bool first = true;
    for (const auto& b : s.bodies) {
        out += first ? "[" : ",[";
        first = false;
        append_int(out, b.id);
        out += ',';
        append_number(out, b.pos_px.x);
        out += ',';
        append_number(out, b.pos_px.y);
        out += ',';
        append_number(out, b.vel_px_s.x);
        out += ',';
        append_number(out, b.vel_px_s.y);
        out += ']';
    }
    out += R"(],"pocketed":[)";
    first = true;
    for (const int id : s.pocketed) {
        if (!first) {
            out += ',';
        }
        first = false;
        append_int(out, id);
    }
    out += ']';
    if (s.due_ms) {
        out += R"(,"due_ms":)";
        append_int(out, *s.due_ms);
    }
    out += '}';
    return out;
}

} // namespace carrom::room
