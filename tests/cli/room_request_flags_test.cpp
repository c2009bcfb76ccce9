// The room-request flags of carrom-client and carrom-bot (cli/): real argument vectors through
// CLI11, the struct they fill, the refusals of the parse and the room-code check after it.
#include "carrom/cli/room_request_flags.hpp"

#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace carrom::cli {
namespace {

using Kind = RoomRequestFlags::Kind;

// Parses `args` (after the program name) with the room flags alone; rethrows CLI11's errors.
RoomRequestFlags parse(std::vector<std::string> args) {
    CLI::App app{"test"};
    RoomRequestFlags flags;
    add_room_request_flags(app, flags);
    args.insert(args.begin(), "program");
    std::vector<char*> argv;
    for (std::string& arg : args) {
        argv.push_back(arg.data());
    }
    app.parse(static_cast<int>(argv.size()), argv.data());
    return flags;
}

// The message of the CLI11 error that parsing `args` throws; "" if it throws none.
std::string refusal(const std::vector<std::string>& args) {
    try {
        parse(args);
    } catch (const CLI::ParseError& e) {
        return e.what();
    }
    return {};
}

TEST(RoomRequestFlags, NoFlagsAskForNoRoomInSinglesOfIcf) {
    const RoomRequestFlags f = parse({});
    EXPECT_EQ(f.kind, Kind::None);
    EXPECT_EQ(f.code, "");
    EXPECT_EQ(f.rule_set, proto::RuleSet::Icf);
    EXPECT_EQ(f.seats, 2);
}

TEST(RoomRequestFlags, CreateWithRuleSetAndSeats) {
    const RoomRequestFlags f = parse({"--create", "--rule-set", "freestyle", "--seats", "4"});
    EXPECT_EQ(f.kind, Kind::Create);
    EXPECT_EQ(f.code, "");
    EXPECT_EQ(f.rule_set, proto::RuleSet::Freestyle);
    EXPECT_EQ(f.seats, 4);
}

TEST(RoomRequestFlags, JoinAndSpectateCarryTheCode) {
    const RoomRequestFlags join = parse({"--join", "ABCDEF"});
    EXPECT_EQ(join.kind, Kind::Join);
    EXPECT_EQ(join.code, "ABCDEF");
    const RoomRequestFlags watch = parse({"--spectate=XYZ234"});
    EXPECT_EQ(watch.kind, Kind::Spectate);
    EXPECT_EQ(watch.code, "XYZ234");
    EXPECT_EQ(watch.seats, 2);
}

TEST(RoomRequestFlags, QuickWithTheRulesAlias) {
    const RoomRequestFlags f = parse({"--quick", "--rules", "discpool", "--seats", "4"});
    EXPECT_EQ(f.kind, Kind::Quick);
    EXPECT_EQ(f.rule_set, proto::RuleSet::DiscPool);
    EXPECT_EQ(f.seats, 4);
    EXPECT_EQ(parse({"--quick", "--rule-set", "seed"}).rule_set, proto::RuleSet::Seed);
}

TEST(RoomRequestFlags, TwoRoomFlagsAreRefused) {
    EXPECT_EQ(refusal({"--create", "--join", "ABCDEF"}), "--create excludes --join");
    EXPECT_EQ(refusal({"--join", "ABCDEF", "--quick"}), "--join excludes --quick");
    EXPECT_EQ(refusal({"--spectate", "ABCDEF", "--create"}), "--create excludes --spectate");
    EXPECT_EQ(refusal({"--quick", "--spectate", "ABCDEF"}), "--spectate excludes --quick");
}

TEST(RoomRequestFlags, SeatsWithAJoinOrAWatchAreRefused) {
    EXPECT_EQ(refusal({"--join", "ABCDEF", "--seats", "4"}), "--join excludes --seats");
    EXPECT_EQ(refusal({"--seats", "2", "--spectate", "ABCDEF"}), "--spectate excludes --seats");
}

TEST(RoomRequestFlags, ValuesOutsideTheListsAreRefused) {
    EXPECT_NE(refusal({"--seats", "3"}).find("--seats"), std::string::npos);
    EXPECT_NE(refusal({"--rule-set", "chess"}).find("--rule-set"), std::string::npos);
    EXPECT_EQ(refusal({"--create", "--seats", "4", "--rule-set", "icf"}), "");
}

TEST(RoomRequestFlags, ARoomCodeOutsideTheAlphabetIsNamed) {
    EXPECT_EQ(room_request_problem(parse({"--join", "ABCDEF"})), "");
    EXPECT_EQ(room_request_problem(parse({"--create"})), "");
    EXPECT_EQ(room_request_problem(parse({"--join", "abcdef"})),
              "a room code is 6 characters from ABCDEFGHJKMNPQRSTUVWXYZ23456789 (got \"abcdef\")");
    EXPECT_EQ(room_request_problem(parse({"--spectate", "ABCDE0"})),
              "a room code is 6 characters from ABCDEFGHJKMNPQRSTUVWXYZ23456789 (got \"ABCDE0\")");
    EXPECT_EQ(room_request_problem(parse({"--join", ""})),
              "a room code is 6 characters from ABCDEFGHJKMNPQRSTUVWXYZ23456789 (got \"\")");
}

} // namespace
} // namespace carrom::cli
