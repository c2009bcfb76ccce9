#pragma once
// The command-line flags that ask a server for a room, shared by carrom-client and carrom-bot:
// --create, --join CODE, --spectate CODE, --quick (at most one of the four), --rule-set NAME and
// --seats 2|4. add_room_request_flags adds them to a CLI11 App; parsing fills a
// RoomRequestFlags. Each program adds its own flags (carrom-client's server bots, carrom-bot's
// room options) and decides what no room flag means.

#include "carrom/proto/types.hpp"

#include <string>

namespace CLI {
class App;
class Option;
} // namespace CLI

namespace carrom::cli {

struct RoomRequestFlags {
    enum class Kind { None, Create, Join, Spectate, Quick };
    Kind kind = Kind::None; // which of --create, --join, --spectate, --quick was given
    std::string code;       // the room code of --join or --spectate; empty otherwise
    proto::RuleSet rule_set = proto::RuleSet::Icf; // --rule-set (alias --rules)
    int seats = 2;                                 // --seats: 2 (singles) or 4 (doubles)
};

// The options added, for a program's own flags to exclude.
struct RoomRequestOptions {
    CLI::Option* create = nullptr;
    CLI::Option* join = nullptr;
    CLI::Option* spectate = nullptr;
    CLI::Option* quick = nullptr;
    CLI::Option* rule_set = nullptr;
    CLI::Option* seats = nullptr;
};

// Adds the flags to `app`; parsing writes them to `flags`, which must outlive the parse. CLI11
// refuses two of the four room flags, --seats with --join or --spectate, a rule set or seat
// count outside the lists.
RoomRequestOptions add_room_request_flags(CLI::App& app, RoomRequestFlags& flags);

// What the parse does not check: a --join or --spectate code outside the room-code alphabet.
// Empty when the flags are good, else one sentence naming the code.
std::string room_request_problem(const RoomRequestFlags& flags);

} // namespace carrom::cli
