// Round trips and validation of server -> client messages.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/json_codec.hpp"

#include "carrom/event.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

using nlohmann::json;

ServerMessage round_trip(const ServerMessage& message) {
    const auto decoded = decode_server(encode(message));
    EXPECT_TRUE(decoded.ok()) << decoded.error.code << ": " << decoded.error.message;
    return decoded.ok() ? *decoded.message : ServerMessage{};
}

std::string error_of(const json& value) {
    const auto decoded = decode_server(value.dump());
    return decoded.ok() ? std::string() : decoded.error.code;
}

RoomState sample_room() {
    RoomState room;
    room.code = "K7M2QX";
    room.you = 1;
    room.rule_set = RuleSet::Seed;
    room.options = MatchOptions{30, 5, 20.0};
    room.seats = {SeatInfo{true, "Asha", true, false, Colour::White, Baseline::Bottom},
                  SeatInfo{true, "Bot", true, true, Colour::Black, Baseline::Top, 1}};
    room.spectators = 3;
    room.scores = {4, -2};
    room.dues = {0, 1};
    room.board_number = 2;
    room.turn = 17;
    room.to_play = 1;
    room.shot_clock_deadline_ms = 1700000020000;
    room.server_time_ms = 1700000000000;
    room.phase = Phase::Aiming;
    room.queen = QueenInfo{QueenState::Pending, 0};
    room.winner = -1;
    room.bodies = {BoardBody{0, BodyKind::Queen, {300.0, 300.0}, {0.0, 0.0}, false},
                   BoardBody{5, BodyKind::White, {57.0, 57.0}, {0.0, 0.0}, true},
                   BoardBody{19, BodyKind::Striker, {300.5, 80.0}, {-1.5, 2.25}, false}};
    return room;
}

TEST(ProtoServer, WelcomeRoundTrip) {
    const Welcome welcome{kProtocolVersion, 42, std::string(32, '0'), 1700000000123};
    EXPECT_EQ(round_trip(welcome), ServerMessage{welcome});
}

TEST(ProtoServer, WelcomeRejectsBadToken) {
    json j = to_json(ServerMessage{Welcome{1, 1, std::string(32, 'a'), 5}});
    j["resume_token"] = "xyz";
    EXPECT_EQ(error_of(j), "bad_field");
}

TEST(ProtoServer, RoomStateRoundTrip) {
    EXPECT_EQ(round_trip(sample_room()), ServerMessage{sample_room()});
    RoomState no_clock = sample_room();
    no_clock.shot_clock_deadline_ms.reset();
    EXPECT_EQ(round_trip(no_clock), ServerMessage{no_clock});
}

TEST(ProtoServer, RoomStateWireNames) {
    const json j = to_json(ServerMessage{sample_room()});
    EXPECT_EQ(j["type"], "room_state");
    EXPECT_EQ(j["seats"][1]["colour"], "black");
    EXPECT_EQ(j["seats"][1]["baseline"], "top");
    EXPECT_EQ(j["seats"][1]["team"], 1);
    EXPECT_EQ(j["queen"], json::parse(R"({"state":"pending","seat":0})"));
    EXPECT_EQ(j["bodies"][2],
              json::parse(R"({"id":19,"kind":"striker","x":300.5,"y":80.0,"vx":-1.5,"vy":2.25,
                              "pocketed":false})"));
    EXPECT_EQ(j["phase"], "aiming");
    EXPECT_EQ(j["rule_set"], "seed");
}

TEST(ProtoServer, RoomStateValidation) {
    const json good = to_json(ServerMessage{sample_room()});
    EXPECT_EQ(error_of(good), "");
    json j = good;
    j["seats"] = json::array({j["seats"][0]});
    EXPECT_EQ(error_of(j), "bad_field"); // one seat
    j = good;
    j["scores"] = json::array({1});
    EXPECT_EQ(error_of(j), "bad_field"); // scores per seat
    j = good;
    j["bodies"][1]["kind"] = "red";
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["bodies"][0]["x"] = 1e300;
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["bodies"][0] = 5;
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["you"] = 4;
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["phase"] = "paused";
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["bodies"] = json::array();
    for (int i = 0; i < 65; ++i) {
        j["bodies"].push_back(good["bodies"][0]);
    }
    EXPECT_EQ(error_of(j), "bad_field"); // over kMaxBodies
}

TEST(ProtoServer, RoomStateMotionIsOptional) {
    RoomState room = sample_room();
    room.motion = {2.5, true};
    EXPECT_EQ(round_trip(room), ServerMessage{room});
    const json j = to_json(ServerMessage{room});
    EXPECT_EQ(j["motion"], json::parse(R"({"damping_per_s":2.5,"contact_snapshots":true})"));
    json absent = j;
    absent.erase("motion");
    const auto decoded = decode_server(absent.dump());
    ASSERT_TRUE(decoded.ok());
    const auto& state = std::get<RoomState>(*decoded.message);
    EXPECT_EQ(state.motion.damping_per_s, PhysicsConfig{}.damping_per_s);
    EXPECT_FALSE(state.motion.contact_snapshots);
}

TEST(ProtoServer, RoomStateMotionValidation) {
    const json good = to_json(ServerMessage{sample_room()});
    for (const char* bad : {R"(5)", R"({"damping_per_s":-1,"contact_snapshots":true})",
                            R"({"damping_per_s":1000,"contact_snapshots":true})",
                            R"({"damping_per_s":"k","contact_snapshots":true})",
                            R"({"damping_per_s":1,"contact_snapshots":"yes"})",
                            R"({"contact_snapshots":true})", R"({"damping_per_s":1})"}) {
        json j = good;
        j["motion"] = json::parse(bad);
        EXPECT_EQ(error_of(j), "bad_field") << bad;
    }
}

TEST(ProtoServer, RoomStateBodyErrorNamesTheIndex) {
    json j = to_json(ServerMessage{sample_room()});
    j["bodies"][2]["vy"] = "fast";
    const auto decoded = decode_server(j.dump());
    ASSERT_FALSE(decoded.ok());
    EXPECT_NE(decoded.error.message.find("bodies[2].vy"), std::string::npos)
        << decoded.error.message;
}

TEST(ProtoServer, SnapshotRoundTripAndCompactBodies) {
    Snapshot snap;
    snap.seq = 99;
    snap.turn = 4;
    snap.t_s = 0.25;
    snap.keyframe = false;
    snap.bodies = {SnapshotBody{19, {300.12, 401.5}, {-12.5, -600.0}},
                   SnapshotBody{3, {250.0, 250.0}, {0.0, 0.0}}};
    snap.pocketed = {7};
    EXPECT_EQ(round_trip(snap), ServerMessage{snap});
    EXPECT_EQ(encode(ServerMessage{snap}),
              R"({"bodies":[[19,300.12,401.5,-12.5,-600.0],[3,250.0,250.0,0.0,0.0]],)"
              R"("keyframe":false,"pocketed":[7],"seq":99,"t":0.25,"turn":4,"type":"snapshot"})");
    snap.due_ms = 1700000000123;
    EXPECT_EQ(round_trip(snap), ServerMessage{snap});
    EXPECT_NE(encode(ServerMessage{snap}).find(R"("due_ms":1700000000123)"), std::string::npos);
}

TEST(ProtoServer, SnapshotValidation) {
    const json good = json::parse(
        R"({"type":"snapshot","seq":1,"turn":0,"t":0.0,"keyframe":true,"bodies":[[1,2,3,4,5]],
            "pocketed":[]})");
    EXPECT_EQ(error_of(good), "");
    json j = good;
    j["bodies"][0] = json::array({1, 2, 3, 4});
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["bodies"][0][0] = 1.5;
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["bodies"][0][3] = "4";
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["bodies"][0][4] = 2e6;
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["t"] = -0.1;
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["pocketed"] = json::array({-1});
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j.erase("keyframe");
    EXPECT_EQ(error_of(j), "bad_field");
    j = good;
    j["due_ms"] = 12345; // optional server clock
    EXPECT_EQ(error_of(j), "");
    for (const json& bad : {json(-1), json(1.5), json("12"), json(nullptr), json(1e300)}) {
        j = good;
        j["due_ms"] = bad;
        EXPECT_EQ(error_of(j), "bad_field") << bad.dump();
    }
}

TEST(ProtoServer, EveryEventKindRoundTrips) {
    const Event events[] = {
        CollisionEvent{3, 0.125, 19, 4, 1234.5},
        CushionEvent{3, 0.5, 4, carrom::kCushionTop, 88.0},
        PocketEvent{3, 1.0, 4, 2},
        FoulEvent{1, "striker_pocketed", "The striker went into a pocket."},
        QueenEvent{QueenInfo{QueenState::Covered, 1}},
        DueEvent{0, 2},
        TurnEvent{4, 1, 1700000020000, 1700000000000},
        TurnEvent{4, 1, std::nullopt, 1700000000000},
        BoardEndEvent{2, 0, 7, {25, 3}},
        GameEndEvent{0, "score", {25, 3}},
        GameEndEvent{0, "score", {25, 3}, "target_points"},
        PlayerDroppedEvent{1, 1700000060000, 1700000000000},
        PlayerReturnedEvent{1},
        AimEvent{0, 4, 250.75},
        EmoteEvent{1, Emote::WellPlayed},
        PausedEvent{"store", "The match waits for the database."},
        ResumedEvent{},
    };
    const char* kinds[] = {"collision",       "cushion",  "pocket",   "foul",
                           "queen",           "due",      "turn",     "turn",
                           "board_end",       "game_end", "game_end", "player_dropped",
                           "player_returned", "aim",      "emote",    "paused",
                           "resumed"};
    for (std::size_t i = 0; i < std::size(events); ++i) {
        EXPECT_EQ(event_kind(events[i]), kinds[i]);
        EXPECT_EQ(to_json(ServerMessage{events[i]})["kind"], kinds[i]);
        EXPECT_EQ(round_trip(events[i]), ServerMessage{events[i]}) << kinds[i];
    }
}

TEST(ProtoServer, GameEndNamesItsRuleOnlyWhenItHasOne) {
    EXPECT_EQ(encode(ServerMessage{Event{GameEndEvent{1, "cleared", {0, 20}, "coins_exhausted"}}}),
              R"({"kind":"game_end","reason":"cleared","rule":"coins_exhausted","scores":[0,20],)"
              R"("type":"event","winner":1})");
    EXPECT_EQ(
        encode(ServerMessage{Event{GameEndEvent{1, "cleared", {0, 20}}}}),
        R"({"kind":"game_end","reason":"cleared","scores":[0,20],"type":"event","winner":1})");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"game_end","winner":0,
                                       "reason":"score","scores":[25,3],"rule":""})")),
              "bad_field");
}

TEST(ProtoServer, EventValidation) {
    EXPECT_EQ(error_of(json::parse(R"({"type":"event"})")), "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"explosion"})")), "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"pocket","turn":1,"t":0,"body":3,
                                       "pocket":4})")),
              "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"cushion","turn":1,"t":0,"body":3,
                                       "cushion":0,"impulse":-1})")),
              "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"turn","turn":1,"seat":4,
                                       "server_time_ms":0})")),
              "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"foul","seat":0,"rule":"",
                                       "message":""})")),
              "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"event","kind":"player_returned","seat":1})")), "");
}

TEST(ProtoServer, ShotResultRoundTrip) {
    ShotResult result;
    result.turn = 8;
    result.seat = 1;
    result.x_px = 200.5;
    result.angle_rad = -1.0;
    result.power = 25.0;
    result.pocketed = {19, 4};
    result.returned = {4};
    result.fouls = {Foul{"striker_pocketed", "The striker went into a pocket."}};
    result.points = {0, -1};
    result.scores = {3, 2};
    result.dues = {0, 1};
    result.queen = QueenInfo{QueenState::OnBoard, -1};
    result.extra_turn = false;
    result.next_turn = 9;
    result.next_seat = 0;
    result.board_over = false;
    result.game_over = false;
    result.winner = -1;
    EXPECT_EQ(round_trip(result), ServerMessage{result});
    json j = to_json(ServerMessage{result});
    j["fouls"][0]["rule"] = std::string(201, 'r');
    EXPECT_EQ(error_of(j), "bad_field");
}

TEST(ProtoServer, ErrorAndPongRoundTrip) {
    EXPECT_EQ(round_trip(Error{"not_your_turn", "It is not your turn."}),
              (ServerMessage{Error{"not_your_turn", "It is not your turn."}}));
    EXPECT_EQ(round_trip(Pong{7, 1700000000000}), (ServerMessage{Pong{7, 1700000000000}}));
    EXPECT_EQ(error_of(json::parse(R"({"type":"error","code":"","message":"x"})")), "bad_field");
    EXPECT_EQ(error_of(json::parse(R"({"type":"pong","nonce":1,"server_time_ms":-5})")),
              "bad_field");
}

TEST(ProtoServer, ServerTypeNames) {
    EXPECT_EQ(type_name(ServerMessage{Welcome{}}), "welcome");
    EXPECT_EQ(type_name(ServerMessage{RoomState{}}), "room_state");
    EXPECT_EQ(type_name(ServerMessage{Snapshot{}}), "snapshot");
    EXPECT_EQ(type_name(ServerMessage{Event{}}), "event");
    EXPECT_EQ(type_name(ServerMessage{ShotResult{}}), "shot_result");
    EXPECT_EQ(type_name(ServerMessage{Error{}}), "error");
    EXPECT_EQ(type_name(ServerMessage{Pong{}}), "pong");
    EXPECT_EQ(type_name(ServerMessage{Redirect{}}), "redirect");
}

} // namespace
} // namespace carrom::proto
