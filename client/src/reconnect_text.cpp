#include "carrom/client/reconnect_text.hpp"

#include <cmath>

namespace carrom::client {

namespace {

// Whole seconds, rounded up (a countdown never shows 0 while time is left); tenths below 10 s.
std::string seconds_text(double s) {
    if (s < 10.0) {
        const long tenths = std::lround(std::ceil(s * 10.0));
        return std::to_string(tenths / 10) + "." + std::to_string(tenths % 10) + " s";
    }
    return std::to_string(std::lround(std::ceil(s))) + " s";
}

} // namespace

ReconnectText reconnect_text(SessionPhase phase, const ReconnectInfo& info,
                             const std::string& status) {
    ReconnectText out;
    if (phase == SessionPhase::Failed) {
        out.title = "Disconnected";
        out.lines.push_back("Connection lost: " + (info.reason.empty() ? status : info.reason));
        if (info.attempt > 0) {
            out.lines.push_back("Gave up after " + std::to_string(info.attempt) +
                                (info.attempt == 1 ? " try." : " tries."));
        }
        return out;
    }
    out.title = "Reconnecting...";
    if (info.trying) {
        out.lines.push_back("Attempt " + std::to_string(info.attempt) + ": connecting.");
    } else {
        out.lines.push_back("Attempt " + std::to_string(info.attempt) + ", next try in " +
                            seconds_text(info.next_try_in_s) + ".");
    }
    if (!info.reason.empty()) {
        out.lines.push_back(info.reason);
    }
    out.lines.push_back("Your seat is held; giving up in " + seconds_text(info.gives_up_in_s) +
                        ".");
    return out;
}

} // namespace carrom::client
