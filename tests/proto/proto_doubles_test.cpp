// The doubles fields of the wire protocol: seat counts in create_room and quick_match, bot seats,
// the four baselines and the team of a seat in room_state. Singles messages keep their shape.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/json_codec.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

using nlohmann::json;

// The decoded message, or a failed expectation and a default message.
template <class M> M decoded_as(const std::string& text) {
    const auto decoded = decode_client(text);
    EXPECT_TRUE(decoded.ok()) << text << ": " << decoded.error.message;
    if (!decoded.ok() || !std::holds_alternative<M>(*decoded.message)) {
        return M{};
    }
    return std::get<M>(*decoded.message);
}

// The bad_field error's sentence for `text` ("" when it decodes or fails otherwise).
std::string bad_field(const std::string& text) {
    const auto decoded = decode_client(text);
    if (decoded.ok() || decoded.error.code != code::kBadField) {
        ADD_FAILURE() << text << " gave " << decoded.error.code;
        return {};
    }
    return decoded.error.message;
}

// --- create_room.seats ---

TEST(ProtoDoubles, CreateRoomSeatsDefaultTwo) {
    EXPECT_EQ(decoded_as<CreateRoom>(R"({"type":"create_room"})").seats, 2);
}

TEST(ProtoDoubles, CreateRoomSeatsTwo) {
    EXPECT_EQ(decoded_as<CreateRoom>(R"({"type":"create_room","seats":2})").seats, 2);
}

TEST(ProtoDoubles, CreateRoomSeatsFour) {
    EXPECT_EQ(decoded_as<CreateRoom>(R"({"type":"create_room","seats":4})").seats, 4);
}

TEST(ProtoDoubles, CreateRoomSeatsThreeRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":3})"), "field 'seats' must be 2 or 4.");
}

TEST(ProtoDoubles, CreateRoomSeatsOneRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":1})"),
              "field 'seats' must be an integer in [2, 4].");
}

TEST(ProtoDoubles, CreateRoomSeatsFiveRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":5})"),
              "field 'seats' must be an integer in [2, 4].");
}

TEST(ProtoDoubles, CreateRoomSeatsNotANumberRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":"4"})"),
              "field 'seats' must be an integer in [2, 4].");
}

TEST(ProtoDoubles, CreateRoomSeatsFractionRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4.5})"),
              "field 'seats' must be an integer in [2, 4].");
}

TEST(ProtoDoubles, CreateRoomSinglesWireShapeUnchanged) {
    EXPECT_EQ(to_json(ClientMessage{CreateRoom{}}),
              json::parse(R"({"type":"create_room","rule_set":"icf","options":{}})"));
}

TEST(ProtoDoubles, CreateRoomDoublesWireShape) {
    CreateRoom create;
    create.seats = 4;
    EXPECT_EQ(to_json(ClientMessage{create}),
              json::parse(R"({"type":"create_room","rule_set":"icf","options":{},"seats":4})"));
}

// --- create_room.bot.seats ---

TEST(ProtoDoubles, BotSeatsAbsentIsEmpty) {
    const auto create = decoded_as<CreateRoom>(R"({"type":"create_room","seats":4,"bot":{}})");
    ASSERT_TRUE(create.bot.has_value());
    EXPECT_TRUE(create.bot->seats.empty());
}

TEST(ProtoDoubles, BotSeatsOnePartner) {
    const auto create =
        decoded_as<CreateRoom>(R"({"type":"create_room","seats":4,"bot":{"seats":[2]}})");
    ASSERT_TRUE(create.bot.has_value());
    EXPECT_EQ(create.bot->seats, (std::vector<int>{2}));
    EXPECT_EQ(create.bot->level, BotLevel::Medium);
}

TEST(ProtoDoubles, BotSeatsThreeInAnyOrder) {
    const auto create = decoded_as<CreateRoom>(
        R"({"type":"create_room","seats":4,"bot":{"level":"easy","seats":[3,1,2]}})");
    ASSERT_TRUE(create.bot.has_value());
    EXPECT_EQ(create.bot->seats, (std::vector<int>{3, 1, 2}));
    EXPECT_EQ(create.bot->level, BotLevel::Easy);
}

TEST(ProtoDoubles, BotSeatsSeatCountReadBeforeBot) {
    // Object member order does not matter: "seats" after "bot" still allows seat 3.
    const auto create =
        decoded_as<CreateRoom>(R"({"type":"create_room","bot":{"seats":[3]},"seats":4})");
    ASSERT_TRUE(create.bot.has_value());
    EXPECT_EQ(create.bot->seats, (std::vector<int>{3}));
}

TEST(ProtoDoubles, BotSeatsSinglesSeatOne) {
    const auto create = decoded_as<CreateRoom>(R"({"type":"create_room","bot":{"seats":[1]}})");
    ASSERT_TRUE(create.bot.has_value());
    EXPECT_EQ(create.bot->seats, (std::vector<int>{1}));
}

TEST(ProtoDoubles, BotSeatsSinglesSeatTwoRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","bot":{"seats":[2]}})"),
              "field 'bot.seats' must hold integers in [1, 1].");
}

TEST(ProtoDoubles, BotSeatsCreatorSeatRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":[0]}})"),
              "field 'bot.seats' must hold integers in [1, 3].");
}

TEST(ProtoDoubles, BotSeatsOutOfRangeRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":[4]}})"),
              "field 'bot.seats' must hold integers in [1, 3].");
}

TEST(ProtoDoubles, BotSeatsNegativeRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":[-1]}})"),
              "field 'bot.seats' must hold integers in [1, 3].");
}

TEST(ProtoDoubles, BotSeatsEmptyRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":[]}})"),
              "field 'bot.seats' must name at least one seat.");
}

TEST(ProtoDoubles, BotSeatsDuplicateRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":[1,3,1]}})"),
              "field 'bot.seats' must not name a seat twice.");
}

TEST(ProtoDoubles, BotSeatsTooManyRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":[1,2,3,1]}})"),
              "field 'bot.seats' must have at most 3 items.");
}

TEST(ProtoDoubles, BotSeatsNotAnArrayRefused) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":4,"bot":{"seats":2}})"),
              "field 'bot.seats' must be an array.");
}

TEST(ProtoDoubles, BotSeatsWithBadSeatCountNamesSeats) {
    EXPECT_EQ(bad_field(R"({"type":"create_room","seats":3,"bot":{"seats":[1]}})"),
              "field 'seats' must be 2 or 4.");
}

TEST(ProtoDoubles, BotSeatsWireShape) {
    CreateRoom create;
    create.seats = 4;
    create.bot = BotSeat{BotLevel::Hard, {1, 3}};
    EXPECT_EQ(to_json(ClientMessage{create}),
              json::parse(R"({"type":"create_room","rule_set":"icf","options":{},"seats":4,
                              "bot":{"level":"hard","seats":[1,3]}})"));
}

TEST(ProtoDoubles, BotWithoutSeatsWireShapeUnchanged) {
    CreateRoom create;
    create.bot = BotSeat{BotLevel::Easy};
    EXPECT_EQ(to_json(ClientMessage{create}),
              json::parse(R"({"type":"create_room","rule_set":"icf","options":{},
                              "bot":{"level":"easy"}})"));
}

TEST(ProtoDoubles, CreateRoomDoublesRoundTrip) {
    CreateRoom create;
    create.rule_set = RuleSet::Seed;
    create.seats = 4;
    create.bot = BotSeat{BotLevel::Random, {2}};
    const auto decoded = decode_client(encode(ClientMessage{create}));
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(*decoded.message, ClientMessage{create});
}

// --- quick_match.seats ---

TEST(ProtoDoubles, QuickMatchSeatsDefaultTwo) {
    EXPECT_EQ(decoded_as<QuickMatch>(R"({"type":"quick_match"})").seats, 2);
}

TEST(ProtoDoubles, QuickMatchSeatsFour) {
    const auto quick =
        decoded_as<QuickMatch>(R"({"type":"quick_match","rule_set":"seed","seats":4})");
    EXPECT_EQ(quick.seats, 4);
    EXPECT_EQ(quick.rule_set, RuleSet::Seed);
}

TEST(ProtoDoubles, QuickMatchSeatsThreeRefused) {
    EXPECT_EQ(bad_field(R"({"type":"quick_match","seats":3})"), "field 'seats' must be 2 or 4.");
}

TEST(ProtoDoubles, QuickMatchSeatsNullRefused) {
    EXPECT_EQ(bad_field(R"({"type":"quick_match","seats":null})"),
              "field 'seats' must be an integer in [2, 4].");
}

TEST(ProtoDoubles, QuickMatchSinglesWireShapeUnchanged) {
    EXPECT_EQ(to_json(ClientMessage{QuickMatch{RuleSet::Icf}}),
              json::parse(R"({"type":"quick_match","rule_set":"icf"})"));
}

TEST(ProtoDoubles, QuickMatchDoublesWireShape) {
    EXPECT_EQ(to_json(ClientMessage{QuickMatch{RuleSet::Freestyle, 4}}),
              json::parse(R"({"type":"quick_match","rule_set":"freestyle","seats":4})"));
}

// --- baselines ---

TEST(ProtoDoubles, BaselineNames) {
    EXPECT_EQ(baseline_name(Baseline::Bottom), "bottom");
    EXPECT_EQ(baseline_name(Baseline::Right), "right");
    EXPECT_EQ(baseline_name(Baseline::Top), "top");
    EXPECT_EQ(baseline_name(Baseline::Left), "left");
}

TEST(ProtoDoubles, BaselineParseRight) {
    Baseline baseline = Baseline::Bottom;
    EXPECT_TRUE(parse("right", baseline));
    EXPECT_EQ(baseline, Baseline::Right);
}

TEST(ProtoDoubles, BaselineParseLeft) {
    Baseline baseline = Baseline::Bottom;
    EXPECT_TRUE(parse("left", baseline));
    EXPECT_EQ(baseline, Baseline::Left);
}

TEST(ProtoDoubles, BaselineParseRefusesOtherNames) {
    Baseline baseline = Baseline::Top;
    EXPECT_FALSE(parse("Left", baseline));
    EXPECT_FALSE(parse("east", baseline));
    EXPECT_FALSE(parse("", baseline));
    EXPECT_EQ(baseline, Baseline::Top);
}

TEST(ProtoDoubles, BaselineIsTheRulesSide) {
    // A seat's baseline is the rules engine's side: rules::striker_for takes it as it is.
    EXPECT_EQ(rules::make_seats(4)[1].side, Baseline::Right);
    EXPECT_EQ(rules::make_seats(4)[3].side, Baseline::Left);
}

// --- room_state with four seats ---

RoomState doubles_room() {
    RoomState room;
    room.code = "K7M2QX";
    room.you = 3;
    room.rule_set = RuleSet::Icf;
    room.seats = {SeatInfo{true, "Asha", true, false, Colour::White, Baseline::Bottom, 0},
                  SeatInfo{true, "Bo", true, false, Colour::Black, Baseline::Right, 1},
                  SeatInfo{true, "Bot", true, true, Colour::White, Baseline::Top, 0},
                  SeatInfo{true, "Cy", false, false, Colour::Black, Baseline::Left, 1}};
    room.scores = {3, 1, 3, 1};
    room.dues = {0, 1, 0, 1};
    room.turn = 5;
    room.to_play = 1;
    room.phase = Phase::Aiming;
    room.winner = -1;
    return room;
}

TEST(ProtoDoubles, RoomStateFourSeatsRoundTrip) {
    const auto decoded = decode_server(encode(ServerMessage{doubles_room()}));
    ASSERT_TRUE(decoded.ok()) << decoded.error.message;
    EXPECT_EQ(*decoded.message, ServerMessage{doubles_room()});
}

TEST(ProtoDoubles, RoomStateSeatWireShape) {
    const json j = to_json(ServerMessage{doubles_room()});
    EXPECT_EQ(j["seats"][1], json::parse(R"({"occupied":true,"name":"Bo","connected":true,
                                             "bot":false,"colour":"black","baseline":"right",
                                             "team":1})"));
    EXPECT_EQ(j["seats"][3]["baseline"], "left");
    EXPECT_EQ(j["seats"][2]["team"], 0);
}

TEST(ProtoDoubles, RoomStateTeamAbsentIsTheSeat) {
    json j = to_json(ServerMessage{doubles_room()});
    for (auto& seat : j["seats"]) {
        seat.erase("team");
    }
    const auto decoded = decode_server(j.dump());
    ASSERT_TRUE(decoded.ok()) << decoded.error.message;
    const auto& room = std::get<RoomState>(*decoded.message);
    ASSERT_EQ(room.seats.size(), 4U);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(room.seats[static_cast<std::size_t>(i)].team, i);
    }
}

TEST(ProtoDoubles, RoomStateTeamOutOfRangeRefused) {
    json j = to_json(ServerMessage{doubles_room()});
    j["seats"][0]["team"] = 4;
    const auto decoded = decode_server(j.dump());
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.code, "bad_field");
}

TEST(ProtoDoubles, RoomStateTeamNegativeRefused) {
    json j = to_json(ServerMessage{doubles_room()});
    j["seats"][0]["team"] = -1;
    const auto decoded = decode_server(j.dump());
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.code, "bad_field");
}

TEST(ProtoDoubles, RoomStateUnknownBaselineRefused) {
    json j = to_json(ServerMessage{doubles_room()});
    j["seats"][1]["baseline"] = "east";
    const auto decoded = decode_server(j.dump());
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.code, "bad_field");
}

TEST(ProtoDoubles, RoomStateThreeSeatsRefused) {
    json j = to_json(ServerMessage{doubles_room()});
    j["seats"].erase(3);
    j["scores"].erase(3);
    j["dues"].erase(3);
    const auto decoded = decode_server(j.dump());
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.message, "field 'seats' must have 2 or 4 items.");
}

TEST(ProtoDoubles, RoomStateScoresPerSeat) {
    json j = to_json(ServerMessage{doubles_room()});
    j["scores"] = json::array({3, 1});
    const auto decoded = decode_server(j.dump());
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.code, "bad_field");
}

TEST(ProtoDoubles, RoomStateWinnerTeamOne) {
    RoomState room = doubles_room();
    room.phase = Phase::GameOver;
    room.winner = 1;
    const auto decoded = decode_server(encode(ServerMessage{room}));
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<RoomState>(*decoded.message).winner, 1);
}

TEST(ProtoDoubles, ShotResultFourSeatsRoundTrip) {
    ShotResult result;
    result.turn = 7;
    result.seat = 3;
    result.points = {0, 1, 0, 1};
    result.scores = {2, 5, 2, 5};
    result.dues = {0, 0, 0, 0};
    result.next_turn = 8;
    result.next_seat = 0;
    const auto decoded = decode_server(encode(ServerMessage{result}));
    ASSERT_TRUE(decoded.ok()) << decoded.error.message;
    EXPECT_EQ(*decoded.message, ServerMessage{result});
}

} // namespace
} // namespace carrom::proto
