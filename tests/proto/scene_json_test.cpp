// Scene JSON codec: every bad field gives its code and path; valid documents round-trip.

#include "carrom/proto/scene_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace carrom::proto {
namespace {

using Json = nlohmann::json;

// Decodes text and returns the error ({"", "", ""} when it decoded).
Error scene_error_of(std::string_view text) {
    auto decoded = decode_scene_text(text);
    return decoded.ok() ? Error{} : *decoded.error;
}

void expect_error(std::string_view text, std::string_view code, std::string_view path) {
    const Error e = scene_error_of(text);
    EXPECT_EQ(e.code, code) << text << "\n" << e.message;
    EXPECT_EQ(e.path, path) << text << "\n" << e.message;
    EXPECT_FALSE(e.message.empty()) << text;
}

// A scene with one body whose JSON is given.
std::string one_body(std::string_view body) {
    return std::string(R"({"bodies": [)") + std::string(body) + "]}";
}

constexpr std::string_view kQueen = R"({"id": 0, "kind": "queen", "pos": [300, 300]})";

void expect_same_body(const Body& a, const Body& b) {
    EXPECT_EQ(a.id, b.id);
    EXPECT_EQ(a.kind, b.kind);
    EXPECT_EQ(a.pos_px, b.pos_px);
    EXPECT_EQ(a.vel_px_s, b.vel_px_s);
    EXPECT_EQ(a.pocketed, b.pocketed);
}

// --- Text -----------------------------------------------------------------------------------

TEST(SceneJsonText, RejectsMalformedJson) {
    expect_error("{", "malformed_json", "");
    expect_error("", "malformed_json", "");
    expect_error("{\"layout\": standard}", "malformed_json", "");
    expect_error("{\"layout\": \"standard\"} x", "malformed_json", "");
}

// The JSON library stops at a NUL byte; text after it must not be ignored.
TEST(SceneJsonText, NulByteIsMalformed) {
    using namespace std::string_literals;
    expect_error("{\"layout\": \"standard\"}\0 garbage"s, "malformed_json", "");
    expect_error("{\"layout\": \"standard\"}\0"s, "malformed_json", "");
    expect_error("{\"layout\": \"stan\0dard\"}"s, "malformed_json", "");
    const Error e = scene_error_of("{\"layout\": \"standard\"}\0 x"s);
    EXPECT_NE(e.message.find("offset 22"), std::string::npos) << e.message;
}

TEST(SceneJsonText, InvalidUtf8IsMalformedAndTheMessageStaysPrintable) {
    for (std::string_view text : {"\xff", "{\"a\xff\": 1}", "{\"layout\": \"\xc3\"}"}) {
        const Error e = scene_error_of(text);
        EXPECT_EQ(e.code, "malformed_json");
        for (char c : e.message) {
            EXPECT_TRUE(c >= 0x20 && c <= 0x7e) << e.message;
        }
        EXPECT_NO_THROW((void)error_to_json(e).dump());
    }
}

TEST(SceneJsonText, NumberOverflowIsMalformed) {
    expect_error(one_body(R"({"id": 0, "kind": "queen", "pos": [1e400, 300]})"), "malformed_json",
                 "");
}

TEST(SceneJsonText, RejectsTextOverTheSizeLimit) {
    const std::string big = "{\"description\": \"" + std::string(kMaxSceneBytes, 'a') + "\"}";
    expect_error(big, "too_large", "");
}

TEST(SceneJsonText, RejectsDeepNesting) {
    const std::string deep =
        std::string(kMaxJsonDepth + 1, '[') + std::string(kMaxJsonDepth + 1, ']');
    expect_error(deep, "too_deep", "");
    const std::string ok_depth = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
    expect_error(ok_depth, "wrong_type", "");
}

TEST(SceneJsonText, BracketsInsideStringsDoNotCountAsNesting) {
    const std::string text =
        R"({"description": ")" + std::string(100, '[') + R"(\"{", "layout": "standard"})";
    EXPECT_TRUE(decode_scene_text(text).ok());
}

TEST(SceneJsonText, RejectsDuplicateKeys) {
    expect_error(R"({"layout": "standard", "layout": "standard"})", "duplicate_key", "");
    expect_error(one_body(R"({"id": 0, "id": 1, "kind": "queen", "pos": [300, 300]})"),
                 "duplicate_key", "");
}

TEST(SceneJsonText, SameKeyInSiblingObjectsIsFine) {
    const auto decoded = decode_scene_text(
        R"({"bodies": [{"id": 0, "kind": "queen", "pos": [300, 300]},
                       {"id": 1, "kind": "black", "pos": [100, 100]}]})");
    ASSERT_TRUE(decoded.ok()) << decoded.error->message;
    EXPECT_EQ(decoded.value.bodies.size(), 2u);
}

TEST(SceneJsonText, GarbageNeverThrows) {
    for (std::string_view text : {"null", "nan", "\"", "[]", "1", "true", "{\"bodies\": [{}]}",
                                  "{\"bodies\": [[]]}", "{\"bodies\": {}}", "{\"config\": []}",
                                  "{\"shot\": 1, \"layout\": 2}", "\xff\xfe", "{\"\\u0000\": 1}"}) {
        EXPECT_FALSE(decode_scene_text(text).ok()) << text;
    }
}

// --- Scene document -------------------------------------------------------------------------

TEST(SceneJsonScene, TopLevelMustBeAnObject) {
    expect_error("[]", "wrong_type", "");
    expect_error("3", "wrong_type", "");
}

TEST(SceneJsonScene, RejectsUnknownTopLevelFields) {
    expect_error(R"({"layout": "standard", "friction": 1})", "unknown_field", "friction");
}

TEST(SceneJsonScene, NeedsBodiesOrLayout) {
    expect_error("{}", "missing_field", "bodies");
    expect_error(R"({"layout": "standard", "bodies": []})", "conflicting_fields", "layout");
}

TEST(SceneJsonScene, UnknownLayoutIsABadValue) {
    expect_error(R"({"layout": "diamond"})", "bad_value", "layout");
    expect_error(R"({"layout": 1})", "wrong_type", "layout");
}

TEST(SceneJsonScene, DescriptionMustBeAShortString) {
    expect_error(R"({"layout": "standard", "description": 5})", "wrong_type", "description");
    const std::string long_text = R"({"layout": "standard", "description": ")" +
                                  std::string(kMaxDescriptionBytes + 1, 'x') + "\"}";
    expect_error(long_text, "out_of_range", "description");
}

TEST(SceneJsonScene, StandardLayoutHasNineteenCoins) {
    const auto decoded = decode_scene_text(R"({"layout": "standard"})");
    ASSERT_TRUE(decoded.ok());
    ASSERT_EQ(decoded.value.bodies.size(), 19u);
    EXPECT_EQ(decoded.value.bodies[0].kind, BodyKind::Queen);
    EXPECT_EQ(decoded.value.bodies[0].pos_px, (Vec2{300, 300}));
}

TEST(SceneJsonScene, ShotAddsTheStrikerOnItsBaseline) {
    const auto decoded = decode_scene_text(
        R"({"layout": "standard",
            "shot": {"baseline": "bottom", "x": 300, "angle": -1.5707963267948966, "power": 25}})");
    ASSERT_TRUE(decoded.ok()) << decoded.error->message;
    ASSERT_EQ(decoded.value.bodies.size(), 20u);
    const Body& striker = decoded.value.bodies.back();
    EXPECT_EQ(striker.id, kStrikerId);
    EXPECT_EQ(striker.kind, BodyKind::Striker);
    EXPECT_EQ(striker.pos_px, (Vec2{300, 520}));
    EXPECT_NEAR(striker.vel_px_s.x, 0.0, 1e-9);
    EXPECT_DOUBLE_EQ(striker.vel_px_s.y, -1500.0);
}

TEST(SceneJsonScene, ShotFromTheTopBaselineDefaultsToBottom) {
    const auto top = decode_scene_text(
        R"({"layout": "standard", "shot": {"baseline": "top", "x": 200, "angle": 1, "power": 5}})");
    ASSERT_TRUE(top.ok());
    EXPECT_EQ(top.value.bodies.back().pos_px, (Vec2{200, 80}));
    const auto bottom =
        decode_scene_text(R"({"layout": "standard", "shot": {"x": 200, "angle": 1, "power": 5}})");
    ASSERT_TRUE(bottom.ok());
    EXPECT_EQ(bottom.value.bodies.back().pos_px, (Vec2{200, 520}));
}

TEST(SceneJsonScene, ShotFieldErrorsNameTheirPath) {
    const std::string head = R"({"layout": "standard", "shot": )";
    expect_error(head + R"({"x": 300, "angle": 0}})", "missing_field", "shot.power");
    expect_error(head + R"({"x": 100, "angle": 0, "power": 5}})", "out_of_range", "shot.x");
    expect_error(head + R"({"x": 488, "angle": 0, "power": 5}})", "out_of_range", "shot.x");
    expect_error(head + R"({"x": 300, "angle": 0, "power": 25.5}})", "out_of_range", "shot.power");
    expect_error(head + R"({"x": 300, "angle": 0, "power": -1}})", "out_of_range", "shot.power");
    expect_error(head + R"({"x": 300, "angle": "up", "power": 5}})", "wrong_type", "shot.angle");
    expect_error(head + R"({"x": 300, "angle": 101, "power": 5}})", "out_of_range", "shot.angle");
    expect_error(head + R"({"x": 300, "angle": 0, "power": 5, "baseline": "left"}})", "bad_value",
                 "shot.baseline");
    expect_error(head + R"({"x": 300, "angle": 0, "power": 5, "spin": 1}})", "unknown_field",
                 "shot.spin");
    expect_error(head + "[]}", "wrong_type", "shot");
}

TEST(SceneJsonScene, ShotRangeFollowsTheConfig) {
    const auto decoded = decode_scene_text(
        R"({"config": {"max_power": 30}, "layout": "standard",
            "shot": {"x": 300, "angle": 0, "power": 26}})");
    ASSERT_TRUE(decoded.ok()) << decoded.error->message;
    EXPECT_DOUBLE_EQ(decoded.value.bodies.back().vel_px_s.x, 26.0 * 60.0);
}

TEST(SceneJsonScene, ShotCanJoinExplicitBodies) {
    const auto decoded =
        decode_scene_text(std::string(R"({"bodies": [)") + std::string(kQueen) +
                          R"(], "shot": {"x": 300, "angle": -1.5707963267948966, "power": 10}})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(decoded.value.bodies.size(), 2u);
}

TEST(SceneJsonScene, StrikerIdClashWithShotPointsAtTheShot) {
    expect_error(
        R"({"bodies": [{"id": 19, "kind": "black", "pos": [100, 100]}],
            "shot": {"x": 300, "angle": 0, "power": 10}})",
        "duplicate_id", "shot");
}

TEST(SceneJsonScene, BodiesMustBeAnArrayOfAtMost64) {
    expect_error(R"({"bodies": {}})", "wrong_type", "bodies");
    std::string many = R"({"bodies": [)";
    for (int i = 0; i < 65; ++i) {
        many += std::string(i ? "," : "") + R"({"id": )" + std::to_string(i) +
                R"(, "kind": "black", "pos": [100, 100]})";
    }
    many += "]}";
    expect_error(many, "too_many", "bodies");
}

TEST(SceneJsonScene, EmptyBodiesIsAValidScene) {
    const auto decoded = decode_scene_text(R"({"bodies": []})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_TRUE(decoded.value.bodies.empty());
}

TEST(SceneJsonScene, OverlapNamesTheBodyAndField) {
    const auto e = scene_error_of(R"({"bodies": [{"id": 4, "kind": "black", "pos": [300, 300]},
                                           {"id": 7, "kind": "white", "pos": [320, 300]}]})");
    EXPECT_EQ(e.code, "overlap");
    EXPECT_EQ(e.path, "bodies[1].pos");
    EXPECT_NE(e.message.find("body 7"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("body 4"), std::string::npos) << e.message;
}

TEST(SceneJsonScene, TouchingBodiesAreNotOverlapping) {
    const auto decoded = decode_scene_text(R"({"bodies": [
        {"id": 0, "kind": "black", "pos": [300, 300]},
        {"id": 1, "kind": "white", "pos": [328, 300]}]})");
    EXPECT_TRUE(decoded.ok());
}

TEST(SceneJsonScene, OutsideTheCushionsNamesTheAxis) {
    expect_error(one_body(R"({"id": 2, "kind": "black", "pos": [48.5, 300]})"), "outside_cushions",
                 "bodies[0].pos.x");
    expect_error(one_body(R"({"id": 2, "kind": "striker", "pos": [300, 548]})"), "outside_cushions",
                 "bodies[0].pos.y");
}

TEST(SceneJsonScene, PocketedBodiesMayLieAnywhere) {
    const auto decoded = decode_scene_text(
        one_body(R"({"id": 2, "kind": "black", "pos": [0, 0], "pocketed": true})"));
    ASSERT_TRUE(decoded.ok());
    EXPECT_TRUE(decoded.value.bodies[0].pocketed);
}

TEST(SceneJsonScene, DuplicateIdsNameTheSecond) {
    expect_error(R"({"bodies": [{"id": 3, "kind": "black", "pos": [100, 100]},
                                {"id": 3, "kind": "white", "pos": [200, 200]}]})",
                 "duplicate_id", "bodies[1].id");
}

// --- Bodies ---------------------------------------------------------------------------------

TEST(SceneJsonBody, DecodesEveryField) {
    const auto decoded = decode_body(
        Json::parse(R"({"id": 7, "kind": "striker", "pos": [120.5, 200], "vel": [-3, 4.25],
                        "pocketed": false})"),
        "b");
    ASSERT_TRUE(decoded.ok());
    expect_same_body(decoded.value, Body{7, BodyKind::Striker, {120.5, 200}, {-3, 4.25}, false});
}

TEST(SceneJsonBody, VelocityDefaultsToRestAndVectorsMayBeObjects) {
    const auto decoded =
        decode_body(Json::parse(R"({"id": 1, "kind": "white", "pos": {"x": 1, "y": 2}})"), "b");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(decoded.value.pos_px, (Vec2{1, 2}));
    EXPECT_EQ(decoded.value.vel_px_s, Vec2{});
}

TEST(SceneJsonBody, EachBadFieldGivesItsCodeAndPath) {
    struct Case {
        const char* body;
        const char* code;
        const char* path;
    };
    const Case cases[] = {
        {R"({"kind": "black", "pos": [100, 100]})", "missing_field", "bodies[0].id"},
        {R"({"id": 0, "pos": [100, 100]})", "missing_field", "bodies[0].kind"},
        {R"({"id": 0, "kind": "black"})", "missing_field", "bodies[0].pos"},
        {R"({"id": -1, "kind": "black", "pos": [100, 100]})", "out_of_range", "bodies[0].id"},
        {R"({"id": 1000001, "kind": "black", "pos": [100, 100]})", "out_of_range", "bodies[0].id"},
        {R"({"id": 18446744073709551615, "kind": "black", "pos": [100, 100]})", "out_of_range",
         "bodies[0].id"},
        {R"({"id": 1.5, "kind": "black", "pos": [100, 100]})", "wrong_type", "bodies[0].id"},
        {R"({"id": "1", "kind": "black", "pos": [100, 100]})", "wrong_type", "bodies[0].id"},
        {R"({"id": 0, "kind": "red", "pos": [100, 100]})", "bad_value", "bodies[0].kind"},
        {R"({"id": 0, "kind": 2, "pos": [100, 100]})", "wrong_type", "bodies[0].kind"},
        {R"({"id": 0, "kind": "black", "pos": [100]})", "wrong_type", "bodies[0].pos"},
        {R"({"id": 0, "kind": "black", "pos": [100, 100, 1]})", "wrong_type", "bodies[0].pos"},
        {R"({"id": 0, "kind": "black", "pos": "100,100"})", "wrong_type", "bodies[0].pos"},
        {R"({"id": 0, "kind": "black", "pos": ["a", 100]})", "wrong_type", "bodies[0].pos.x"},
        {R"({"id": 0, "kind": "black", "pos": [100, null]})", "wrong_type", "bodies[0].pos.y"},
        {R"({"id": 0, "kind": "black", "pos": [100, true]})", "wrong_type", "bodies[0].pos.y"},
        {R"({"id": 0, "kind": "black", "pos": [10001, 100]})", "out_of_range", "bodies[0].pos.x"},
        {R"({"id": 0, "kind": "black", "pos": {"x": 100}})", "missing_field", "bodies[0].pos.y"},
        {R"({"id": 0, "kind": "black", "pos": {"x": 1, "y": 2, "z": 3}})", "unknown_field",
         "bodies[0].pos.z"},
        {R"({"id": 0, "kind": "black", "pos": [100, 100], "vel": [0, 1000001]})", "out_of_range",
         "bodies[0].vel.y"},
        {R"({"id": 0, "kind": "black", "pos": [100, 100], "vel": 5})", "wrong_type",
         "bodies[0].vel"},
        {R"({"id": 0, "kind": "black", "pos": [100, 100], "pocketed": "no"})", "wrong_type",
         "bodies[0].pocketed"},
        {R"({"id": 0, "kind": "black", "pos": [100, 100], "color": "red"})", "unknown_field",
         "bodies[0].color"},
        {R"(7)", "wrong_type", "bodies[0]"},
    };
    for (const Case& c : cases) {
        expect_error(one_body(c.body), c.code, c.path);
    }
}

TEST(SceneJsonBody, IndexInPathCountsFromZero) {
    expect_error(R"({"bodies": [{"id": 0, "kind": "queen", "pos": [300, 300]},
                                {"id": 1, "kind": "black", "pos": [100, 100]},
                                {"id": 2, "kind": "black", "pos": [200, 200], "vel": [0, "x"]}]})",
                 "wrong_type", "bodies[2].vel.y");
}

TEST(SceneJsonBody, NonFiniteNumbersBuiltInMemoryAreRejected) {
    Json body{{"id", 0}, {"kind", "black"}, {"pos", {100.0, 100.0}}};
    body["vel"] = Json::array({std::numeric_limits<double>::infinity(), 0.0});
    const auto decoded = decode_body(body, "body");
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error->code, "not_finite");
    EXPECT_EQ(decoded.error->path, "body.vel.x");
}

// --- Config ---------------------------------------------------------------------------------

TEST(SceneJsonConfig, OverridesOnlyTheGivenFields) {
    const auto decoded =
        decode_config(Json::parse(R"({"disc_restitution": 0.5, "max_events": 7})"));
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(decoded.value.disc_restitution, 0.5);
    EXPECT_EQ(decoded.value.max_events, 7);
    EXPECT_EQ(decoded.value.cushion_restitution, PhysicsConfig{}.cushion_restitution);
    EXPECT_EQ(decoded.value.damping_per_s, PhysicsConfig{}.damping_per_s);
}

TEST(SceneJsonConfig, EmptyObjectGivesTheDefaults) {
    const auto decoded = decode_config(Json::object());
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(config_to_json(decoded.value), config_to_json(PhysicsConfig{}));
}

TEST(SceneJsonConfig, EachBadFieldGivesItsCodeAndPath) {
    struct Case {
        const char* config;
        const char* code;
        const char* path;
    };
    const Case cases[] = {
        {R"({"friction": 0.9})", "unknown_field", "config.friction"},
        {R"({"disc_restitution": 1.5})", "out_of_range", "config.disc_restitution"},
        {R"({"disc_restitution": -0.1})", "out_of_range", "config.disc_restitution"},
        {R"({"disc_restitution": "0.9"})", "wrong_type", "config.disc_restitution"},
        {R"({"cushion_restitution": null})", "wrong_type", "config.cushion_restitution"},
        {R"({"coin_radius_px": 0})", "out_of_range", "config.coin_radius_px"},
        {R"({"striker_mass": -2})", "out_of_range", "config.striker_mass"},
        {R"({"damping_per_s": -1e-9})", "out_of_range", "config.damping_per_s"},
        {R"({"stop_speed_px_s": 0})", "out_of_range", "config.stop_speed_px_s"},
        {R"({"board_size_px": 1e6})", "out_of_range", "config.board_size_px"},
        {R"({"max_power": 1001})", "out_of_range", "config.max_power"},
        {R"({"max_events": 0})", "out_of_range", "config.max_events"},
        {R"({"max_events": 2.5})", "wrong_type", "config.max_events"},
        {R"({"max_events": 500001})", "out_of_range", "config.max_events"},
        {R"({"frame_px": 290})", "invalid_config", "config.frame_px"},
        {R"({"baseline_offset_px": 10})", "invalid_config", "config.baseline_offset_px"},
    };
    for (const Case& c : cases) {
        expect_error(std::string(R"({"layout": "standard", "config": )") + c.config + "}", c.code,
                     c.path);
    }
    expect_error(R"({"layout": "standard", "config": [1]})", "wrong_type", "config");
}

TEST(SceneJsonConfig, NonFiniteNumbersBuiltInMemoryAreRejected) {
    const Json config{{"disc_restitution", std::nan("")}};
    const auto decoded = decode_config(config);
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error->code, "not_finite");
    EXPECT_EQ(decoded.error->path, "config.disc_restitution");
}

TEST(SceneJsonConfig, ConfigAppliesToTheCushionCheck) {
    // With 10 px coins, x = 45 is inside the cushions (35 + 10).
    const auto decoded = decode_scene_text(
        R"({"config": {"coin_radius_px": 10}, "bodies": [{"id": 0, "kind": "black", "pos": [45, 300]}]})");
    EXPECT_TRUE(decoded.ok());
}

TEST(SceneJsonConfig, EveryFieldRoundTrips) {
    PhysicsConfig c;
    c.board_size_px = 700;
    c.frame_px = 40;
    c.coin_radius_px = 15;
    c.striker_radius_px = 19;
    c.coin_mass = 1.5;
    c.striker_mass = 2.5;
    c.damping_per_s = 0.1 / 3.0;
    c.stop_speed_px_s = 5;
    c.cushion_restitution = 0.7;
    c.disc_restitution = 0.8;
    c.restitution_floor_px_s = 3;
    c.pocket_radius_px = 25;
    c.max_power = 30;
    c.power_to_speed = 50;
    c.baseline_offset_px = 90;
    c.baseline_end_margin_px = 50;
    c.max_events = 1234;
    const Json j = config_to_json(c);
    EXPECT_EQ(j.size(), 17u);
    const auto decoded = decode_config(Json::parse(j.dump()));
    ASSERT_TRUE(decoded.ok()) << decoded.error->message;
    EXPECT_EQ(config_to_json(decoded.value), j);
    EXPECT_EQ(config_overrides_to_json(c).size(), 17u);
}

TEST(SceneJsonConfig, OverridesListOnlyChangedFields) {
    EXPECT_EQ(config_overrides_to_json(PhysicsConfig{}), Json::object());
    PhysicsConfig c;
    c.disc_restitution = 0.3;
    EXPECT_EQ(config_overrides_to_json(c), (Json{{"disc_restitution", 0.3}}));
}

// --- Round trips ----------------------------------------------------------------------------

TEST(SceneJsonRoundTrip, SceneSurvivesEncodeAndDecode) {
    SceneSpec scene;
    scene.config.disc_restitution = 0.75;
    scene.bodies = {Body{0, BodyKind::Queen, {300, 300}, {0.1, -1.0 / 3.0}, false},
                    Body{5, BodyKind::White, {100.25, 411.125}, {}, false},
                    Body{19, BodyKind::Striker, {300, 520}, {1e-7, -1499.999999}, false},
                    Body{8, BodyKind::Black, {0, 0}, {}, true}};
    const std::string text = scene_to_json(scene).dump();
    const auto decoded = decode_scene_text(text);
    ASSERT_TRUE(decoded.ok()) << decoded.error->message;
    EXPECT_EQ(decoded.value.config.disc_restitution, 0.75);
    ASSERT_EQ(decoded.value.bodies.size(), scene.bodies.size());
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        expect_same_body(decoded.value.bodies[i], scene.bodies[i]);
    }
}

TEST(SceneJsonRoundTrip, DefaultConfigIsLeftOut) {
    SceneSpec scene;
    scene.bodies = {Body{0, BodyKind::Queen, {300, 300}, {}, false}};
    EXPECT_FALSE(scene_to_json(scene).contains("config"));
}

TEST(SceneJsonRoundTrip, ShotEncodesAsTheDecoderReadsIt) {
    const ShotSpec shot{carrom::Baseline::Top, Shot{250.5, 1.25, 12.5}};
    const Json j = shot_to_json(shot);
    EXPECT_EQ(j, Json::parse(R"({"baseline": "top", "x": 250.5, "angle": 1.25, "power": 12.5})"));
    const auto decoded = decode_shot(j, PhysicsConfig{});
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(decoded.value.baseline, carrom::Baseline::Top);
    EXPECT_EQ(decoded.value.shot.x_px, 250.5);
    EXPECT_EQ(decoded.value.shot.angle_rad, 1.25);
    EXPECT_EQ(decoded.value.shot.power, 12.5);
}

TEST(SceneJsonRoundTrip, EventSurvivesEncodeAndDecode) {
    const carrom::Event event{0.123456789012345, EventKind::Cushion, 19, kCushionBottom, 2.5e3,
                              {300.5, 547.0}};
    const Json j = event_to_json(event);
    EXPECT_EQ(j["kind"], "cushion");
    const auto decoded = decode_event(Json::parse(j.dump()), "e");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(decoded.value.t_s, event.t_s);
    EXPECT_EQ(decoded.value.kind, event.kind);
    EXPECT_EQ(decoded.value.a, 19);
    EXPECT_EQ(decoded.value.b, kCushionBottom);
    EXPECT_EQ(decoded.value.impulse, event.impulse);
    EXPECT_EQ(decoded.value.pos_px, event.pos_px);
}

TEST(SceneJsonRoundTrip, EventErrorsNameTheirPath) {
    Json j = event_to_json(carrom::Event{1.0, EventKind::Stop, 3, -1, 0.0, {100, 100}});
    j["kind"] = "bounce";
    auto decoded = decode_event(j, "events[2]");
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error->code, "bad_value");
    EXPECT_EQ(decoded.error->path, "events[2].kind");
    j["kind"] = "stop";
    j["t_s"] = -1.0;
    decoded = decode_event(j, "events[2]");
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error->path, "events[2].t_s");
    EXPECT_EQ(decoded.error->code, "out_of_range");
}

TEST(SceneJsonRoundTrip, SimResultSurvivesEncodeAndDecode) {
    SimResult result;
    result.bodies = {Body{0, BodyKind::Queen, {300, 300}, {}, false},
                     Body{19, BodyKind::Striker, {57, 57}, {}, true}};
    result.events = {carrom::Event{0.5, EventKind::Collision, 19, 0, 1234.5, {300, 332}},
                     carrom::Event{1.5, EventKind::Pocket, 19, 0, 0.0, {57, 57}}};
    result.end_time_s = 2.25;
    result.truncated = true;
    result.stats = SimStats{12, 3, 1, 40};
    const Json j = sim_result_to_json(result);
    EXPECT_EQ(j["pocketed"], Json::array({19}));
    const auto decoded = decode_sim_result(Json::parse(j.dump()));
    ASSERT_TRUE(decoded.ok()) << decoded.error->message;
    EXPECT_EQ(sim_result_to_json(decoded.value), j);
    EXPECT_EQ(decoded.value.stats.pair_tests, 40);
}

TEST(SceneJsonRoundTrip, SimResultPocketedListMustMatchTheBodies) {
    SimResult result;
    result.bodies = {Body{0, BodyKind::Queen, {300, 300}, {}, false}};
    Json j = sim_result_to_json(result);
    j["pocketed"] = Json::array({0});
    const auto decoded = decode_sim_result(j);
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error->code, "bad_value");
    EXPECT_EQ(decoded.error->path, "pocketed");
}

TEST(SceneJsonRoundTrip, ErrorEncodesCodePathAndMessage) {
    const Json j = error_to_json(Error{"overlap", "body 1 overlaps body 0", "bodies[1].pos"});
    EXPECT_EQ(j, Json::parse(R"({"error": {"code": "overlap", "path": "bodies[1].pos",
                                           "message": "body 1 overlaps body 0"}})"));
}

} // namespace
} // namespace carrom::proto
