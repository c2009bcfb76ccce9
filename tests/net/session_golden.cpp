#include "session_golden.hpp"

#include "carrom/proto/types.hpp"

#include <array>
#include <stdexcept>

namespace carrom::net::golden {
namespace {

using nlohmann::json;

json action_json(const SessionCore& core, const SessionAction& action) {
    json out{{"kind", std::string(session_action_name(action.kind))}};
    if (action.kind == SessionActionKind::SendJoin) {
        out["code"] = core.join_code();
        out["as"] = std::string(proto::to_string(core.join_as()));
    }
    if (action.kind == SessionActionKind::Wait) {
        out["wait_s"] = action.wait_s;
    }
    if (action.kind == SessionActionKind::GiveUp) {
        out["reason"] = std::string(give_up_reason_name(action.reason));
    }
    return out;
}

SessionActions feed(SessionCore& core, const json& step) {
    const std::string event = step.at("event");
    const double t = step.at("t");
    if (event == "start") {
        return core.start(step.value("resume_token", std::string()));
    }
    if (event == "request") {
        return core.request();
    }
    if (event == "leave") {
        return core.leave();
    }
    if (event == "link_opened") {
        return core.link_opened();
    }
    if (event == "link_closed") {
        return core.link_closed(t, step.at("close_code"), step.at("jitter"));
    }
    if (event == "tick") {
        return core.tick(t);
    }
    if (event == "welcome") {
        return core.welcome(step.at("token"));
    }
    if (event == "room_state") {
        return core.room_state();
    }
    if (event == "error") {
        return core.error(step.at("code").get<std::string>());
    }
    if (event == "redirect") {
        proto::Redirect redirect;
        redirect.url = step.at("url");
        redirect.reason = step.at("reason");
        redirect.code = step.value("code", std::string());
        redirect.as = step.value("as", std::string("player")) == "spectator"
                          ? proto::Role::Spectator
                          : proto::Role::Player;
        return core.redirect(redirect);
    }
    throw std::invalid_argument("unknown event " + event);
}

} // namespace

ReconnectPolicy policy_from_name(const std::string& name) {
    for (const ReconnectPolicy policy :
         {ReconnectPolicy::Always, ReconnectPolicy::SeatOnly, ReconnectPolicy::Never}) {
        if (policy_name(policy) == name) {
            return policy;
        }
    }
    throw std::invalid_argument("unknown policy " + name);
}

std::string policy_name(ReconnectPolicy policy) {
    static const std::array<std::string, 3> kNames{"always", "seat_only", "never"};
    return kNames.at(static_cast<std::size_t>(policy)); // in the enumerators' order
}

SessionCore core_for(const json& golden_case) {
    const json& b = golden_case.at("backoff");
    return SessionCore(BackoffSettings{b.at("first_s"), b.at("cap_s"), b.at("give_up_after_s")},
                       policy_from_name(golden_case.at("policy")),
                       golden_case.at("address").get<std::string>());
}

json play(SessionCore& core, const json& step) {
    json actions = json::array();
    for (const SessionAction& action : feed(core, step)) {
        actions.push_back(action_json(core, action));
    }
    const json state{{"phase", std::string(session_phase_name(core.phase()))},
                     {"tries", core.tries()},
                     {"resuming", core.resuming()},
                     {"wants_room", core.wants_room()},
                     {"link_up", core.link_up()},
                     {"token", core.token()},
                     {"url", core.url()},
                     {"redirects", core.redirects()}};
    return json{{"actions", std::move(actions)}, {"state", state}};
}

} // namespace carrom::net::golden
