// carrom-load's reader of message heads (bots/app/message_head.hpp) on the server's own text, on
// the same messages re-serialised with other key orders and spacing, and on malformed text.
#include "message_head.hpp"

#include "carrom/proto/codec.hpp"
#include "carrom/room/snapshot_writer.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace carrom::load {
namespace {

proto::Snapshot server_delta() {
    proto::Snapshot delta;
    delta.seq = 1234;
    delta.turn = 17;
    delta.t_s = 0.73;
    delta.keyframe = false;
    delta.bodies = {{0, {412.37, 388.12}, {-120.55, 340.21}}, {5, {300.5, 410.25}, {60.12, -22.4}}};
    delta.pocketed = {9};
    delta.due_ms = 123456789;
    return delta;
}

MessageHead delta_head(double t_s, std::optional<std::int64_t> due_ms) {
    return MessageHead{"snapshot", "", SnapshotFields{false, t_s, due_ms}};
}

// The JSON object of `text` with its keys in reverse order, written with `indent` spaces.
std::string reversed_keys(const std::string& text, int indent) {
    const auto parsed = nlohmann::ordered_json::parse(text);
    nlohmann::ordered_json reversed = nlohmann::ordered_json::object();
    for (auto it = parsed.crbegin(); it != parsed.crend(); ++it) {
        reversed[it.key()] = it.value();
    }
    return reversed.dump(indent);
}

std::string collision_text() {
    return proto::encode(
        proto::ServerMessage{proto::Event{proto::CollisionEvent{3, 0.41, 1, 2, 12.5}}});
}

TEST(LoadMessageHead, ReadsTheServersDelta) {
    const auto read = read_message_head(room::encode_snapshot(server_delta()));
    ASSERT_TRUE(read.ok()) << read.error.message;
    EXPECT_EQ(*read.message, delta_head(0.73, 123456789));
}

TEST(LoadMessageHead, ReadsTheSameDeltaInAnyKeyOrderAndSpacing) {
    const std::string server_text = room::encode_snapshot(server_delta());
    // nlohmann::json keeps keys sorted ("type" last) and dump(2) puts each on a line of its own.
    const std::string sorted_indented = nlohmann::json::parse(server_text).dump(2);
    const std::string reversed_indented = reversed_keys(server_text, 4);
    ASSERT_NE(sorted_indented.find("\n  \"type\": \"snapshot\"\n}"), std::string::npos);
    ASSERT_EQ(reversed_indented.rfind("{\n    \"due_ms\": 123456789,", 0), 0U);
    for (const std::string& text : {sorted_indented, reversed_indented,
                                    proto::encode(proto::ServerMessage{server_delta()})}) {
        const auto read = read_message_head(text);
        ASSERT_TRUE(read.ok()) << text << "\n" << read.error.message;
        EXPECT_EQ(*read.message, delta_head(0.73, 123456789)) << text;
    }
}

TEST(LoadMessageHead, ReadsADeltaWithoutDueMs) {
    proto::Snapshot delta = server_delta();
    delta.due_ms.reset();
    const auto read = read_message_head(room::encode_snapshot(delta));
    ASSERT_TRUE(read.ok()) << read.error.message;
    EXPECT_EQ(*read.message, delta_head(0.73, std::nullopt));
}

TEST(LoadMessageHead, ReadsNothingOfAKeyframeButThatItIsOne) {
    proto::Snapshot keyframe = server_delta();
    keyframe.keyframe = true;
    keyframe.due_ms.reset();
    const std::string server_text = room::encode_snapshot(keyframe);
    const MessageHead keyframe_head{"snapshot", "", SnapshotFields{true, 0.0, std::nullopt}};
    for (const std::string& text : {server_text, reversed_keys(server_text, 2)}) {
        const auto read = read_message_head(text);
        ASSERT_TRUE(read.ok()) << text << "\n" << read.error.message;
        EXPECT_EQ(*read.message, keyframe_head) << text;
    }
}

TEST(LoadMessageHead, ReadsOnlyTheTopLevelFields) {
    const auto read = read_message_head(
        R"({"extra":{"type":"event","t":5,"keyframe":true,"due_ms":1},"list":[{"t":6}],)"
        R"("type":"snapshot","keyframe":false,"t":1,"due_ms":2})");
    ASSERT_TRUE(read.ok()) << read.error.message;
    EXPECT_EQ(*read.message, delta_head(1.0, 2));
}

TEST(LoadMessageHead, ReadsTheTypeOfOtherMessagesAndTheKindOfEvents) {
    const std::string pong = proto::encode(proto::ServerMessage{proto::Pong{}});
    const std::string turn = proto::encode(proto::ServerMessage{proto::Event{proto::TurnEvent{}}});
    EXPECT_EQ(*read_message_head(pong).message, (MessageHead{"pong", "", {}}));
    EXPECT_EQ(*read_message_head(turn).message, (MessageHead{"event", "turn", {}}));
    for (const std::string& text : {collision_text(), reversed_keys(collision_text(), 2)}) {
        const auto read = read_message_head(text);
        ASSERT_TRUE(read.ok()) << text << "\n" << read.error.message;
        EXPECT_EQ(*read.message, (MessageHead{"event", "collision", {}})) << text;
    }
}

TEST(LoadMessageHead, ReadsEscapedNamesAndPassesOverEveryKindOfValue) {
    const auto read = read_message_head(
        R"({"\u0074ype":"snap\u0073hot","k\u0065yframe":false,"t":-1.5E+2,"due_ms":-7,)"
        R"("s":"\"\\\/\b\f\n\r\t\ud83c\udfaf \u00e9 Ã© ð¯","n":[null,true,)"
        R"(false,0,-0.0e-0,{},[],{"a":[{}]}]})");
    ASSERT_TRUE(read.ok()) << read.error.message;
    EXPECT_EQ(*read.message, delta_head(-150.0, -7));
}

TEST(LoadMessageHead, PassesOverValuesNestedUpTo64Deep) {
    // The message's object is the first level, so 63 arrays make 64.
    const std::string deepest =
        R"({"type":"event","x":)" + std::string(63, '[') + std::string(63, ']') + R"(,"kind":"k"})";
    const auto read = read_message_head(deepest);
    ASSERT_TRUE(read.ok()) << read.error.message;
    EXPECT_EQ(*read.message, (MessageHead{"event", "k", {}}));
}

struct HeadRefusal {
    std::string text;
    std::string_view code;
    std::string message;
};

constexpr std::string_view kNotJson = "The message is not valid JSON: ";

// Text that breaks the JSON grammar: refused as malformed with simdjson's sentence.
HeadRefusal malformed(std::string text) {
    return {std::move(text), proto::code::kMalformedJson, std::string(kNotJson)};
}

TEST(LoadMessageHead, RefusesMalformedTextWithAnError) {
    const std::string server_text = room::encode_snapshot(server_delta());
    const std::string truncated = server_text.substr(0, server_text.size() - 5);
    const HeadRefusal head_refusals[] = {
        malformed(""),
        malformed(truncated),
        malformed(server_text + " x"),
        malformed(std::string("{\"type\":\"event\"}\0{", 18)),
        malformed(R"({"type":"event","x":01})"),
        malformed(R"({"type":"event","x":1.})"),
        malformed(R"({"type":"event","x":-})"),
        malformed(R"({"type":"event","x":tru})"),
        malformed(R"({"type":"event","x":"\x"})"),
        malformed(R"({"type":"event","x":"\udc00"})"),
        malformed("{\"type\":\"event\",\"x\":\"\t\"}"),
        malformed("{\"type\":\"event\",\"x\":\"\xc3\x28\"}"),
        malformed(R"({"type":"event","x":[1,]})"),
        malformed(R"({"type":"event","x":{"a"}})"),
        malformed(R"({"type":"event",})"),
        malformed(R"({"type":"event","x":)" + std::string(65, '[') + std::string(65, ']') + "}"),
        malformed(R"({"x":nul,"type":"pong"})"),
        malformed(R"({"type":"event","x":fals,"kind":"k"})"),
        malformed(R"({"\q":1,"type":"pong"})"),
        malformed(R"({"type":"snapshot","keyframe":false,"t":1,"b":[{"p":[1,02]}]})"),
        malformed(R"({"type":"snapshot","keyframe":false,"t":1,"due_ms":2}})"),
        {"{}", proto::code::kMissingType, "A message must have a string field 'type'."},
        {"[1,2]", proto::code::kNotObject, "A message must be a JSON object."},
        {"\"snapshot\"", proto::code::kNotObject, "A message must be a JSON object."},
        {R"({"t":1,"keyframe":false})", proto::code::kMissingType,
         "A message must have a string field 'type'."},
        {R"({"type":["snapshot"],"t":1})", proto::code::kMissingType,
         "A message must have a string field 'type'."},
        {R"({"type":"event","t":1})", proto::code::kBadField,
         "An event must have a string field 'kind'."},
        {R"({"type":"event","kind":3})", proto::code::kBadField,
         "An event must have a string field 'kind'."},
        {R"({"type":"snapshot","t":1})", proto::code::kBadField,
         "A snapshot must have a boolean field 'keyframe'."},
        {R"({"type":"snapshot","keyframe":1,"t":1})", proto::code::kBadField,
         "A snapshot must have a boolean field 'keyframe'."},
        {R"({"type":"snapshot","keyframe":false,"t":"1"})", proto::code::kBadField,
         "A delta must have a number field 't'."},
        {R"({"type":"snapshot","keyframe":false,"t":1,"due_ms":1.5})", proto::code::kBadField,
         "A delta's field 'due_ms' must be an integer."},
        {R"({"type":"snapshot","keyframe":false,"t":1,"due_ms":9223372036854775808})",
         proto::code::kBadField, "A delta's field 'due_ms' must be an integer."},
    };
    for (const HeadRefusal& refusal : head_refusals) {
        const auto read = read_message_head(refusal.text);
        EXPECT_FALSE(read.ok()) << refusal.text;
        EXPECT_EQ(read.error.code, refusal.code) << refusal.text;
        if (refusal.code == proto::code::kMalformedJson) {
            EXPECT_EQ(read.error.message.rfind(kNotJson, 0), 0U) << read.error.message;
        } else {
            EXPECT_EQ(read.error.message, refusal.message) << refusal.text;
        }
    }
}

TEST(LoadMessageHead, NamesTheByteWhereSimdjsonFindsAnError) {
    const auto read = read_message_head(R"({"type":"event","x":01})");
    EXPECT_EQ(read.error.code, proto::code::kMalformedJson);
    EXPECT_EQ(read.error.message,
              "The message is not valid JSON: Problem while parsing a number (byte 21).");
}

} // namespace
} // namespace carrom::load
