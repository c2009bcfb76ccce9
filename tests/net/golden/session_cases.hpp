#pragma once
// The golden session cases' building blocks, shared by carrom-session-golden's lists of cases
// (session_golden_main.cpp, redirect_cases.cpp): events in the files' words, and a case.
#include "session_golden.hpp"

#include <string>
#include <vector>

namespace carrom::net::golden {

using nlohmann::json;

// The server address the player gave, in every case.
inline const std::string kAddress = "ws://127.0.0.1:7777";

inline json at(double t, const std::string& event, json args = json::object()) {
    args["t"] = t;
    args["event"] = event;
    return args;
}

inline json closed(double t, int code = 1006, double jitter = 1.0) {
    return at(t, "link_closed", {{"close_code", code}, {"jitter", jitter}});
}

inline json welcome(double t, const std::string& token) {
    return at(t, "welcome", {{"token", token}});
}

inline json error(double t, const std::string& code) {
    return at(t, "error", {{"code", code}});
}

inline const std::string kToken = "5f0c1e0e8a7b4c2d9e3f1a2b3c4d5e6f";
inline const std::string kOther = "0123456789abcdef0123456789abcdef";

// Asks for a room, connects, is welcomed with kToken and gets the room's state by t + 0.4.
inline std::vector<json> into_room(double t) {
    return {at(t, "request"), at(t, "start"), at(t + 0.1, "link_opened"), welcome(t + 0.2, kToken),
            at(t + 0.3, "room_state")};
}

// The next try, due at `t`: the link opens and says hello.
inline std::vector<json> retry(double t) {
    return {at(t, "tick"), at(t, "link_opened")};
}

// In a room by 0.4 s, the link lost at 1 s and tried again at 1.5 s (the first wait, 0.5 s).
inline std::vector<json> in_room_lost_and_retried() {
    std::vector<json> out = into_room(0.0);
    out.push_back(closed(1.0));
    for (json& step : retry(1.5)) {
        out.push_back(std::move(step));
    }
    return out;
}

struct Case {
    std::string name;
    std::string about;
    std::vector<json> events;
    ReconnectPolicy policy = ReconnectPolicy::Always;
    BackoffSettings backoff{};
    std::string address = kAddress;
};

inline void add(std::vector<json>& to, const std::vector<json>& events) {
    to.insert(to.end(), events.begin(), events.end());
}

// The redirect cases (redirect_cases.cpp).
std::vector<Case> redirect_cases();

} // namespace carrom::net::golden
