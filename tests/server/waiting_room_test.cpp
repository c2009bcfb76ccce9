// The description of a room a draining instance hands over (server/src/waiting_room.hpp): it
// round-trips exactly, and a description that is not one is refused with bad_waiting_room and
// a sentence naming what is wrong.
#include "waiting_room.hpp"

#include "carrom/room/room.hpp"

#include <gtest/gtest.h>

namespace carrom::server {
namespace {

proto::Error refusal(std::string_view description) {
    const auto read = read_waiting_room(description);
    EXPECT_TRUE(std::holds_alternative<proto::Error>(read)) << description;
    return std::holds_alternative<proto::Error>(read) ? std::get<proto::Error>(read)
                                                      : proto::Error{};
}

TEST(WaitingRoom, ADescriptionRoundTripsTheRuleSetEveryRuleAndRated) {
    proto::RoomOptions options;
    options.boards = 3;
    WaitingRoomSpec spec{proto::RuleSet::Seed,
                         room::make_rules_config(proto::RuleSet::Seed, options, 25.0), true};
    spec.rules.seat_count = 4;
    const auto read = read_waiting_room(describe_waiting_room(spec));
    ASSERT_TRUE(std::holds_alternative<WaitingRoomSpec>(read));
    const auto& back = std::get<WaitingRoomSpec>(read);
    EXPECT_EQ(back.rule_set, proto::RuleSet::Seed);
    EXPECT_EQ(back.rules, spec.rules);
    EXPECT_TRUE(back.rated);
}

TEST(WaitingRoom, NotAnObjectIsRefused) {
    EXPECT_EQ(refusal("[1]").code, "bad_waiting_room");
    EXPECT_EQ(refusal("{").message, "A handed-over room's description is not a JSON object.");
}

TEST(WaitingRoom, AnUnknownOrMissingRuleSetIsRefused) {
    EXPECT_EQ(refusal(R"({"rule_set":"chess","rules":{},"rated":false})").message,
              "A handed-over room's description has no known rule_set.");
    EXPECT_EQ(refusal(R"({"rules":{},"rated":false})").message,
              "A handed-over room's description has no known rule_set.");
}

TEST(WaitingRoom, RatedMustBeABoolean) {
    EXPECT_EQ(refusal(R"({"rule_set":"icf","rules":{},"rated":1})").message,
              "A handed-over room's description has no boolean rated.");
}

TEST(WaitingRoom, ARuleOutOfItsRangeIsRefusedWithItsPath) {
    EXPECT_EQ(refusal(R"({"rule_set":"icf","rated":false})").message,
              "A handed-over room's description has no rules object.");
    const proto::Error error =
        refusal(R"({"rule_set":"icf","rules":{"seat_count":3},"rated":false})");
    EXPECT_EQ(error.message.find("A handed-over room's description has a bad rule "
                                 "(rules.seat_count): "),
              0U)
        << error.message;
}

} // namespace
} // namespace carrom::server
