// room_state's "aim_assist": always sent, optional when read (absent: on), a boolean only.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/json_codec.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

using nlohmann::json;

RoomState aim_assist_room() {
    RoomState room;
    room.code = "K7M2QX";
    room.seats.resize(2);
    room.scores = {0, 0};
    room.dues = {0, 0};
    return room;
}

std::optional<RoomState> decoded_room_state(const json& j) {
    const auto d = decode_server(j.dump());
    if (!d.ok()) {
        return std::nullopt;
    }
    return std::get<RoomState>(*d.message);
}

TEST(ProtoAimAssist, OnByDefault) {
    EXPECT_TRUE(RoomState{}.aim_assist);
}

TEST(ProtoAimAssist, SentWhenOn) {
    EXPECT_EQ(to_json(ServerMessage{aim_assist_room()})["aim_assist"], true);
}

TEST(ProtoAimAssist, SentWhenOff) {
    RoomState room = aim_assist_room();
    room.aim_assist = false;
    EXPECT_EQ(to_json(ServerMessage{room})["aim_assist"], false);
}

TEST(ProtoAimAssist, OffRoundTrips) {
    RoomState room = aim_assist_room();
    room.aim_assist = false;
    const auto back = decoded_room_state(to_json(ServerMessage{room}));
    ASSERT_TRUE(back.has_value());
    EXPECT_FALSE(back->aim_assist);
}

TEST(ProtoAimAssist, AbsentReadsAsOn) {
    RoomState room = aim_assist_room();
    room.aim_assist = false;
    json j = to_json(ServerMessage{room});
    j.erase("aim_assist");
    const auto back = decoded_room_state(j);
    ASSERT_TRUE(back.has_value());
    EXPECT_TRUE(back->aim_assist);
}

TEST(ProtoAimAssist, ANonBooleanIsRefused) {
    for (const json& bad : {json(1), json("true"), json(nullptr), json::array()}) {
        json j = to_json(ServerMessage{aim_assist_room()});
        j["aim_assist"] = bad;
        const auto d = decode_server(j.dump());
        ASSERT_FALSE(d.ok()) << bad.dump();
        EXPECT_EQ(d.error.code, "bad_field") << bad.dump();
    }
}

} // namespace
} // namespace carrom::proto
