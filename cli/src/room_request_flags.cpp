#include "carrom/cli/room_request_flags.hpp"

#include "carrom/proto/limits.hpp"

#include <CLI/CLI.hpp>

#include <vector>

namespace carrom::cli {

namespace {

std::vector<std::string> rule_set_names() {
    std::vector<std::string> names;
    for (const proto::RuleSet r : {proto::RuleSet::Icf, proto::RuleSet::Seed,
                                   proto::RuleSet::Freestyle, proto::RuleSet::DiscPool}) {
        names.emplace_back(proto::to_string(r));
    }
    return names;
}

// --join or --spectate: a room code that also says which of the two the program asks for.
CLI::Option* add_code_option(CLI::App& app, const std::string& name, RoomRequestFlags::Kind kind,
                             RoomRequestFlags& flags, const std::string& description) {
    return app.add_option_function<std::string>(
        name,
        [&flags, kind](const std::string& code) {
            flags.kind = kind;
            flags.code = code;
        },
        description);
}

} // namespace

RoomRequestOptions add_room_request_flags(CLI::App& app, RoomRequestFlags& flags) {
    using Kind = RoomRequestFlags::Kind;
    RoomRequestOptions o;
    o.create = app.add_flag_callback(
        "--create", [&flags] { flags.kind = Kind::Create; }, "Create a private room (seat 0)");
    o.join = add_code_option(app, "--join", Kind::Join, flags,
                             "Join the room with this code as a player");
    o.spectate =
        add_code_option(app, "--spectate", Kind::Spectate, flags, "Watch the room with this code");
    o.quick = app.add_flag_callback(
        "--quick", [&flags] { flags.kind = Kind::Quick; },
        "Quick match: play the next waiting player");
    o.create->excludes(o.join)->excludes(o.spectate)->excludes(o.quick);
    o.join->excludes(o.spectate)->excludes(o.quick);
    o.spectate->excludes(o.quick);
    o.rule_set = app.add_option_function<std::string>(
                        "--rule-set,--rules",
                        [&flags](const std::string& name) { proto::parse(name, flags.rule_set); },
                        "Rule set for --create and --quick")
                     ->check(CLI::IsMember(rule_set_names()))
                     ->default_str(std::string(proto::to_string(flags.rule_set)));
    o.seats = app.add_option("--seats", flags.seats,
                             "With --create or --quick: 2 (singles) or 4 (doubles: partners "
                             "opposite)")
                  ->capture_default_str()
                  ->check(CLI::IsMember({2, 4}));
    o.seats->excludes(o.join)->excludes(o.spectate);
    return o;
}

std::string room_request_problem(const RoomRequestFlags& flags) {
    using Kind = RoomRequestFlags::Kind;
    if ((flags.kind != Kind::Join && flags.kind != Kind::Spectate) ||
        proto::is_room_code(flags.code)) {
        return {};
    }
    return "a room code is " + std::to_string(proto::kRoomCodeLength) + " characters from " +
           proto::kRoomCodeAlphabet + " (got \"" + flags.code + "\")";
}

} // namespace carrom::cli
