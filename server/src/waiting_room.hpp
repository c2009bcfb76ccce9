#pragma once
// Private to server/src: a room that waits for its players, as a draining instance hands it to
// another (docs/cluster.md, "Draining"). The description is JSON text the store keeps as it is:
// {"rule_set": "icf", "rules": {every rule, as in a journal's head}, "rated": false}. Boost-free.

#include "carrom/proto/error.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/rules/rules_config.hpp"

#include <string>
#include <string_view>
#include <variant>

namespace carrom::server {

// What a room is opened again from: its rule set, every rule (the room's options and seat
// count included) and whether it is rated.
struct WaitingRoomSpec {
    proto::RuleSet rule_set = proto::RuleSet::Icf;
    rules::RulesConfig rules{};
    bool rated = false;
};

std::string describe_waiting_room(const WaitingRoomSpec& spec);
// The spec of a description, or why it is none (code bad_waiting_room, one sentence naming the
// field): not JSON, an unknown rule set, a rule out of its range, a missing field.
std::variant<WaitingRoomSpec, proto::Error> read_waiting_room(std::string_view description);

} // namespace carrom::server
