// Round trips and validation of client -> server messages.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/json_codec.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

using nlohmann::json;

ClientMessage round_trip(const ClientMessage& message) {
    const auto decoded = decode_client(encode(message));
    EXPECT_TRUE(decoded.ok()) << decoded.error.code << ": " << decoded.error.message;
    return decoded.ok() ? *decoded.message : ClientMessage{};
}

// Decodes `text` and returns the error code ("" on success).
std::string error_of(const std::string& text) {
    const auto decoded = decode_client(text);
    return decoded.ok() ? std::string() : decoded.error.code;
}

TEST(ProtoClient, HelloRoundTrip) {
    const Hello hello{kProtocolVersion, "Asha", std::nullopt};
    EXPECT_EQ(round_trip(hello), ClientMessage{hello});
    const Hello resume{kProtocolVersion, "Asha", std::string(32, 'a')};
    EXPECT_EQ(round_trip(resume), ClientMessage{resume});
}

TEST(ProtoClient, HelloWireShape) {
    const json j = to_json(ClientMessage{Hello{1, "Bo", std::nullopt}});
    EXPECT_EQ(j, json::parse(R"({"type":"hello","version":1,"name":"Bo"})"));
}

TEST(ProtoClient, CreateRoomRoundTrip) {
    CreateRoom create;
    create.rule_set = RuleSet::Freestyle;
    create.options.target_points = 170;
    create.options.boards = 3;
    create.options.shot_clock_s = 12.5;
    create.bot = BotSeat{BotLevel::Hard};
    EXPECT_EQ(round_trip(create), ClientMessage{create});
    EXPECT_EQ(round_trip(CreateRoom{}), ClientMessage{CreateRoom{}});
}

TEST(ProtoClient, CreateRoomDefaultsWhenFieldsAbsent) {
    const auto decoded = decode_client(R"({"type":"create_room"})");
    ASSERT_TRUE(decoded.ok());
    const auto& create = std::get<CreateRoom>(*decoded.message);
    EXPECT_EQ(create.rule_set, RuleSet::Icf);
    EXPECT_FALSE(create.options.target_points.has_value());
    EXPECT_FALSE(create.bot.has_value());
}

TEST(ProtoClient, CreateRoomBotWithoutLevelIsMedium) {
    const auto decoded = decode_client(R"({"type":"create_room","bot":{}})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<CreateRoom>(*decoded.message).bot->level, BotLevel::Medium);
}

TEST(ProtoClient, CreateRoomRejectsBadOptions) {
    EXPECT_EQ(error_of(R"({"type":"create_room","rule_set":"snooker"})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","rule_set":7})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","options":[]})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","options":{"target_points":0}})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","options":{"target_points":1001}})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","options":{"boards":100}})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","options":{"shot_clock_s":-1}})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","options":{"shot_clock_s":601}})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","bot":{"level":"godlike"}})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"create_room","bot":true})"), "bad_field");
}

TEST(ProtoClient, NestedFieldErrorNamesThePath) {
    const auto decoded = decode_client(R"({"type":"create_room","options":{"boards":"8"}})");
    ASSERT_FALSE(decoded.ok());
    EXPECT_NE(decoded.error.message.find("options.boards"), std::string::npos)
        << decoded.error.message;
}

TEST(ProtoClient, JoinRoomRoundTrip) {
    const JoinRoom join{"K7M2QX", Role::Spectator};
    EXPECT_EQ(round_trip(join), ClientMessage{join});
}

TEST(ProtoClient, JoinRoomDefaultsToPlayer) {
    const auto decoded = decode_client(R"({"type":"join_room","code":"ABCDEF"})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<JoinRoom>(*decoded.message).as, Role::Player);
}

TEST(ProtoClient, JoinRoomRejectsBadCodes) {
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"ABCDE"})"), "bad_field");   // short
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"ABCDEFG"})"), "bad_field"); // long
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"abcdef"})"), "bad_field");  // lowercase
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"ABCDE0"})"), "bad_field");  // zero
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"ABCDEO"})"), "bad_field");  // letter O
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"ABCDE1"})"), "bad_field");  // one
    EXPECT_EQ(error_of(R"({"type":"join_room","code":123456})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"join_room"})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"join_room","code":"ABCDEF","as":"referee"})"), "bad_field");
}

TEST(ProtoClient, QuickMatchRoundTrip) {
    EXPECT_EQ(round_trip(QuickMatch{RuleSet::DiscPool}),
              (ClientMessage{QuickMatch{RuleSet::DiscPool}}));
    const auto decoded = decode_client(R"({"type":"quick_match"})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<QuickMatch>(*decoded.message).rule_set, RuleSet::Icf);
}

TEST(ProtoClient, AimRoundTrip) {
    EXPECT_EQ(round_trip(Aim{3, 301.25}), (ClientMessage{Aim{3, 301.25}}));
}

TEST(ProtoClient, ShootRoundTripKeepsExactDoubles) {
    const Shoot shoot{12, 113.00000000000001, -1.5707963267948966, 24.999999999999996};
    EXPECT_EQ(round_trip(shoot), ClientMessage{shoot});
}

TEST(ProtoClient, ShootWireShape) {
    const json j = to_json(ClientMessage{Shoot{2, 300.0, 0.5, 20.0}});
    EXPECT_EQ(j, json::parse(R"({"type":"shoot","turn":2,"x":300.0,"angle":0.5,"power":20.0})"));
}

TEST(ProtoClient, ShootAcceptsIntegersForNumbers) {
    const auto decoded = decode_client(R"({"type":"shoot","turn":0,"x":300,"angle":0,"power":25})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<Shoot>(*decoded.message), (Shoot{0, 300.0, 0.0, 25.0}));
}

TEST(ProtoClient, ShootRangeEdges) {
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":0,"angle":-100,"power":0})"), "");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":1000000,"x":10000,"angle":100,"power":1000})"),
              "");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":-1,"x":300,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":1000001,"x":300,"angle":0,"power":1})"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":-0.001,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":10000.5,"angle":0,"power":1})"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":100.01,"power":1})"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":0,"power":-1e-9})"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":0,"power":1000.1})"),
              "bad_field");
}

TEST(ProtoClient, TurnMustBeAnInteger) {
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":1.0,"x":300,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":1e2,"x":300,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":"1","x":300,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":true,"x":300,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":null,"x":300,"angle":0,"power":1})"), "bad_field");
}

TEST(ProtoClient, NumbersMustBeNumbers) {
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":"300","angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":[300],"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":null,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":0,"power":false})"),
              "bad_field");
}

TEST(ProtoClient, MissingFieldsAreBadFields) {
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":0})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"aim","turn":0})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"ping"})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","name":"A"})"), "bad_field");
}

TEST(ProtoClient, HugeAndNonFiniteNumbersAreRejected) {
    // nlohmann rejects a number that overflows a double at parse time.
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":1e400,"angle":0,"power":1})"),
              "malformed_json");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":-1e400,"angle":0,"power":1})"),
              "malformed_json");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":NaN,"angle":0,"power":1})"),
              "malformed_json");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":Infinity,"angle":0,"power":1})"),
              "malformed_json");
    // Finite but far out of range.
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":1e308,"angle":0,"power":1})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":18446744073709551616,"x":3,"angle":0,"power":1})"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":18446744073709551615,"x":3,"angle":0,"power":1})"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":-9223372036854775808,"x":3,"angle":0,"power":1})"),
              "bad_field");
    // Underflow parses as zero, which is in range.
    EXPECT_EQ(error_of(R"({"type":"shoot","turn":0,"x":300,"angle":1e-400,"power":1})"), "");
}

TEST(ProtoClient, ANulByteAnywhereIsMalformedJson) {
    using namespace std::string_literals;
    EXPECT_EQ(error_of("{\"type\":\"ping\",\"nonce\":1}\0garbage"s), "malformed_json");
    EXPECT_EQ(error_of("{\"type\":\"ping\",\"nonce\":1}\0"s), "malformed_json");
    EXPECT_EQ(error_of("{\"type\":\"hello\",\"version\":1,\"name\":\"A\0B\"}"s), "malformed_json");
    const auto decoded = decode_client("{\"type\":\"ping\",\"nonce\":1}\0x"s);
    EXPECT_EQ(decoded.error.message, "The message is not valid JSON (a NUL byte at byte 25).");
    EXPECT_EQ(decode_server("{}\0"s).error.code, "malformed_json");
}

TEST(ProtoClient, HelloNameRules) {
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":""})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"   "})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"a\tb"})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"a\u0000b"})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"a\u007fb"})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":")" + std::string(24, 'n') + "\"}"),
              "");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":")" + std::string(25, 'n') + "\"}"),
              "bad_field");
    // Multi-byte UTF-8 counts bytes: 8 x 3-byte characters = 24 bytes is fine, 9 is not.
    std::string eight;
    for (int i = 0; i < 8; ++i) {
        eight += "\xe0\xa4\x85";
    }
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":")" + eight + "\"}"), "");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":")" + eight + "\xe0\xa4\x85\"}"),
              "bad_field");
    // Invalid UTF-8 is a JSON error.
    EXPECT_EQ(error_of("{\"type\":\"hello\",\"version\":1,\"name\":\"\xff\"}"), "malformed_json");
}

TEST(ProtoClient, ResumeTokenRules) {
    const std::string good(32, 'f');
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"A","resume_token":")" + good + "\"}"),
              "");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"A","resume_token":")" +
                       std::string(31, 'f') + "\"}"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"A","resume_token":")" +
                       std::string(32, 'F') + "\"}"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"A","resume_token":")" +
                       std::string(32, 'g') + "\"}"),
              "bad_field");
    EXPECT_EQ(error_of(R"({"type":"hello","version":1,"name":"A","resume_token":null})"),
              "bad_field");
}

TEST(ProtoClient, OtherVersionsDecodeSoTheServerCanAnswerThem) {
    const auto decoded = decode_client(R"({"type":"hello","version":99,"name":"A"})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<Hello>(*decoded.message).version, 99);
}

TEST(ProtoClient, EmptyMessagesRoundTrip) {
    EXPECT_EQ(round_trip(Rematch{}), ClientMessage{Rematch{}});
    EXPECT_EQ(round_trip(Leave{}), ClientMessage{Leave{}});
    EXPECT_EQ(encode(ClientMessage{Leave{}}), R"({"type":"leave"})");
}

TEST(ProtoClient, PingRoundTripAndRange) {
    EXPECT_EQ(round_trip(Ping{kMaxNonce}), ClientMessage{Ping{kMaxNonce}});
    EXPECT_EQ(error_of(R"({"type":"ping","nonce":9007199254740992})"), "bad_field");
    EXPECT_EQ(error_of(R"({"type":"ping","nonce":-1})"), "bad_field");
}

TEST(ProtoClient, UnknownFieldsAreIgnored) {
    const auto decoded = decode_client(R"({"type":"ping","nonce":5,"extra":{"deep":[1,2,3]}})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<Ping>(*decoded.message).nonce, 5);
}

TEST(ProtoClient, DuplicateKeysKeepTheLast) {
    const auto decoded = decode_client(R"({"type":"ping","nonce":5,"nonce":6})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<Ping>(*decoded.message).nonce, 6);
}

TEST(ProtoClient, EveryTypeNameIsDistinctAndRoundTrips) {
    const ClientMessage all[] = {Hello{1, "A", std::nullopt},
                                 CreateRoom{},
                                 JoinRoom{"ABCDEF"},
                                 QuickMatch{},
                                 Aim{},
                                 Shoot{},
                                 Rematch{},
                                 Leave{},
                                 Ping{},
                                 EmoteMessage{Emote::Sorry}};
    const char* names[] = {"hello", "create_room", "join_room", "quick_match", "aim",
                           "shoot", "rematch",     "leave",     "ping",        "emote"};
    for (std::size_t i = 0; i < std::size(all); ++i) {
        EXPECT_EQ(type_name(all[i]), names[i]);
        EXPECT_EQ(round_trip(all[i]), all[i]) << names[i];
    }
}

} // namespace
} // namespace carrom::proto

namespace carrom::proto {
namespace {

std::string hello_with_identity(const std::string& identity_json) {
    return R"({"type":"hello","version":1,"name":"A","identity":)" + identity_json + "}";
}

TEST(ProtoClient, HelloIdentityRoundTripAndWireShape) {
    Hello hello{kProtocolVersion, "Asha", std::nullopt};
    hello.identity = std::string(64, 'e');
    EXPECT_EQ(round_trip(hello), ClientMessage{hello});
    EXPECT_EQ(to_json(ClientMessage{hello})["identity"], std::string(64, 'e'));
    EXPECT_FALSE(to_json(ClientMessage{Hello{1, "Bo", std::nullopt}}).contains("identity"));
}

TEST(ProtoClient, HelloIdentityIsAnyShortTextOnTheWireTheServerJudgesItsForm) {
    EXPECT_EQ(error_of(hello_with_identity("\"" + std::string(64, 'a') + "\"")), "");
    EXPECT_EQ(error_of(hello_with_identity("\"XYZ\"")), ""); // the server answers bad_identity
    EXPECT_EQ(error_of(hello_with_identity("\"\"")), "bad_field");
    EXPECT_EQ(error_of(hello_with_identity("\"" + std::string(129, 'a') + "\"")), "bad_field");
    EXPECT_EQ(error_of(hello_with_identity("42")), "bad_field");
    EXPECT_EQ(error_of(hello_with_identity("null")), "bad_field");
}

TEST(ProtoClient, IdentityKeyIs64LowercaseHexDigits) {
    EXPECT_TRUE(is_identity_key(std::string(64, '0')));
    EXPECT_TRUE(is_identity_key(std::string(32, 'a') + std::string(32, '9')));
    EXPECT_FALSE(is_identity_key(std::string(63, 'a')));
    EXPECT_FALSE(is_identity_key(std::string(65, 'a')));
    EXPECT_FALSE(is_identity_key(std::string(64, 'A')));
    EXPECT_FALSE(is_identity_key(std::string(63, 'a') + "g"));
}

TEST(ProtoClient, CreateRoomRatedOnTheWireOnlyWhenTrue) {
    CreateRoom create;
    create.rated = true;
    EXPECT_EQ(round_trip(create), ClientMessage{create});
    EXPECT_EQ(to_json(ClientMessage{create})["rated"], true);
    EXPECT_FALSE(to_json(ClientMessage{CreateRoom{}}).contains("rated"));
    EXPECT_EQ(error_of(R"({"type":"create_room","rated":"yes"})"), "bad_field");
    const auto decoded = decode_client(R"({"type":"create_room","rated":false})");
    ASSERT_TRUE(decoded.ok());
    EXPECT_FALSE(std::get<CreateRoom>(*decoded.message).rated);
}

} // namespace
} // namespace carrom::proto
