#include "waiting_room.hpp"

#include "carrom/proto/match_json.hpp"

#include <nlohmann/json.hpp>

namespace carrom::server {
namespace {

proto::Error bad(std::string message) {
    return proto::Error{"bad_waiting_room",
                        "A handed-over room's description " + std::move(message)};
}

} // namespace

std::string describe_waiting_room(const WaitingRoomSpec& spec) {
    const nlohmann::json j = {{"rule_set", std::string(proto::to_string(spec.rule_set))},
                              {"rules", proto::rules_config_to_json(spec.rules)},
                              {"rated", spec.rated}};
    return j.dump();
}

std::variant<WaitingRoomSpec, proto::Error> read_waiting_room(std::string_view description) {
    const auto j = nlohmann::json::parse(description, nullptr, false);
    if (!j.is_object()) {
        return bad("is not a JSON object.");
    }
    WaitingRoomSpec spec;
    const auto rule_set = j.find("rule_set");
    if (rule_set == j.end() || !rule_set->is_string() ||
        !proto::parse(rule_set->get<std::string>(), spec.rule_set)) {
        return bad("has no known rule_set.");
    }
    const auto rated = j.find("rated");
    if (rated == j.end() || !rated->is_boolean()) {
        return bad("has no boolean rated.");
    }
    spec.rated = rated->get<bool>();
    const auto rules = j.find("rules");
    if (rules == j.end() || !rules->is_object()) {
        return bad("has no rules object.");
    }
    auto decoded = proto::decode_rules_config(*rules);
    if (!decoded.ok()) {
        return bad("has a bad rule (" + decoded.error->path + "): " + decoded.error->message);
    }
    spec.rules = decoded.value;
    return spec;
}

} // namespace carrom::server
