#pragma once
// tests/golden/session/*.json and net::SessionCore: one event of a case fed to the core, and
// what it answered (actions and the state after them), in the files' words. Shared by the
// generator (golden/session_golden_main.cpp, carrom-session-golden) and the replay test
// (session_golden_test.cpp); web/js's port replays the same files (tests/web/session_test.mjs).
//
// A case file: {"name", "about", "address" (the server address the player gave), "backoff":
// {"first_s", "cap_s", "give_up_after_s"}, "policy": "always" | "seat_only" | "never", "steps":
// [step...]}; a step: {"t" (seconds), "event", its arguments ("resume_token", "close_code" and
// "jitter", "token", "code"; redirect: "url", "reason", "code"?, "as"?), "actions": [{"kind",
// "wait_s"?, "reason"?, "code"? and "as"? (send_join)}...], "state": {"phase", "tries",
// "resuming", "wants_room", "link_up", "token", "url", "redirects"}}.

#include "carrom/net/session_core.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace carrom::net::golden {

ReconnectPolicy policy_from_name(const std::string& name);
std::string policy_name(ReconnectPolicy policy);

// The core a case starts from.
SessionCore core_for(const nlohmann::json& golden_case);

// Feeds step's event to the core; returns {"actions": [...], "state": {...}}.
nlohmann::json play(SessionCore& core, const nlohmann::json& step);

} // namespace carrom::net::golden
