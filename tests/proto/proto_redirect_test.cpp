// The messages of redirects between the instances of a cluster (docs/protocol.md, "Redirects"):
// `redirect`, hello's `follows_redirects`, and the `paused` / `resumed` events.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/json_codec.hpp"
#include "carrom/proto/limits.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

using nlohmann::json;

// The decoded server message of `text`; fails the test when it does not decode.
ServerMessage redirect_suite_decode(const std::string& text) {
    const auto decoded = decode_server(text);
    EXPECT_TRUE(decoded.ok()) << text << ": " << decoded.error.code << ": "
                              << decoded.error.message;
    return decoded.ok() ? *decoded.message : ServerMessage{};
}

// The error code decoding `text` gives ("" when it decodes).
std::string redirect_suite_error(const std::string& text) {
    const auto decoded = decode_server(text);
    return decoded.ok() ? std::string() : decoded.error.code;
}

const char* const kUrl = "ws://127.0.0.1:7801/i/b/";

TEST(ProtoRedirect, WireShapeWithARoom) {
    EXPECT_EQ(encode(ServerMessage{Redirect{kUrl, "room", "K7M2QX", Role::Spectator}}),
              R"({"as":"spectator","code":"K7M2QX","reason":"room","type":"redirect",)"
              R"("url":"ws://127.0.0.1:7801/i/b/"})");
    EXPECT_EQ(encode(ServerMessage{Redirect{kUrl, "quick_match", "K7M2QX", Role::Player}}),
              R"({"as":"player","code":"K7M2QX","reason":"quick_match","type":"redirect",)"
              R"("url":"ws://127.0.0.1:7801/i/b/"})");
}

TEST(ProtoRedirect, WireShapeWithoutARoomHasNoAs) {
    EXPECT_EQ(encode(ServerMessage{Redirect{kUrl, "seat", "", Role::Spectator}}),
              R"({"reason":"seat","type":"redirect","url":"ws://127.0.0.1:7801/i/b/"})");
}

TEST(ProtoRedirect, RoundTrips) {
    for (const Redirect& r : {Redirect{kUrl, "room", "K7M2QX", Role::Player},
                              Redirect{kUrl, "moved", "ABCDEF", Role::Spectator},
                              Redirect{"wss://carrom.example/i/c/", "seat", "", Role::Player},
                              Redirect{"ws://h", "quick_match", "Z23456", Role::Player}}) {
        EXPECT_EQ(redirect_suite_decode(encode(ServerMessage{r})), ServerMessage{r}) << r.url;
    }
}

TEST(ProtoRedirect, TypeName) {
    EXPECT_EQ(type_name(ServerMessage{Redirect{}}), "redirect");
}

TEST(ProtoRedirect, AsDefaultsToPlayer) {
    const ServerMessage m = redirect_suite_decode(
        R"({"type":"redirect","url":"ws://h:1/","reason":"room","code":"K7M2QX"})");
    EXPECT_EQ(std::get<Redirect>(m), (Redirect{"ws://h:1/", "room", "K7M2QX", Role::Player}));
}

TEST(ProtoRedirect, AsWithoutACodeIsIgnored) {
    const ServerMessage m = redirect_suite_decode(
        R"({"type":"redirect","url":"ws://h:1/","reason":"seat","as":"spectator"})");
    EXPECT_EQ(std::get<Redirect>(m), (Redirect{"ws://h:1/", "seat", "", Role::Player}));
}

TEST(ProtoRedirect, UrlMustBeWsOrWss) {
    for (const char* url :
         {"http://h:1/", "https://h:1/", "WS://h:1/", "ftp://h:1/", "ws:/h:1/x", "/i/b/", "h:1"}) {
        const json j{{"type", "redirect"}, {"url", url}, {"reason", "room"}};
        EXPECT_EQ(redirect_suite_error(j.dump()), "bad_field") << url;
    }
    const json j{{"type", "redirect"}, {"url", "wss://h"}, {"reason", "room"}};
    EXPECT_EQ(redirect_suite_error(j.dump()), "");
}

TEST(ProtoRedirect, UrlOfAtLeastSixAndAtMost2000Bytes) {
    const auto with_url = [](const std::string& url) {
        return json{{"type", "redirect"}, {"url", url}, {"reason", "room"}}.dump();
    };
    EXPECT_EQ(redirect_suite_error(with_url("ws://")), "bad_field");
    EXPECT_EQ(redirect_suite_error(with_url("ws://h")), "");
    const std::string base = "ws://h:1/";
    EXPECT_EQ(redirect_suite_error(with_url(base + std::string(kMaxUrlBytes - base.size(), 'a'))),
              "");
    EXPECT_EQ(
        redirect_suite_error(with_url(base + std::string(kMaxUrlBytes + 1 - base.size(), 'a'))),
        "bad_field");
}

TEST(ProtoRedirect, MissingOrEmptyFieldsAreBadFields) {
    for (const char* text :
         {R"({"type":"redirect"})", R"({"type":"redirect","reason":"room"})",
          R"({"type":"redirect","url":"ws://h:1/"})",
          R"({"type":"redirect","url":"ws://h:1/","reason":""})",
          R"({"type":"redirect","url":7,"reason":"room"})",
          R"({"type":"redirect","url":"ws://h:1/","reason":"room","code":null})"}) {
        EXPECT_EQ(redirect_suite_error(text), "bad_field") << text;
    }
    const json long_reason{
        {"type", "redirect"}, {"url", "ws://h:1/"}, {"reason", std::string(33, 'r')}};
    EXPECT_EQ(redirect_suite_error(long_reason.dump()), "bad_field");
}

TEST(ProtoRedirect, CodeMustBeARoomCode) {
    for (const char* code : {"K7M2Q", "K7M2QXY", "k7m2qx", "K7M2Q0", "K7M2QI", "", "K7 2QX"}) {
        const json j{
            {"type", "redirect"}, {"url", "ws://h:1/"}, {"reason", "room"}, {"code", code}};
        EXPECT_EQ(redirect_suite_error(j.dump()), "bad_field") << code;
    }
}

TEST(ProtoRedirect, AsMustBePlayerOrSpectator) {
    for (const json& as : {json("referee"), json(""), json(1), json(nullptr)}) {
        const json j{{"type", "redirect"},
                     {"url", "ws://h:1/"},
                     {"reason", "room"},
                     {"code", "K7M2QX"},
                     {"as", as}};
        EXPECT_EQ(redirect_suite_error(j.dump()), "bad_field") << as.dump();
    }
}

TEST(ProtoHelloFollowsRedirects, SentOnlyWhenTrue) {
    Hello hello{kProtocolVersion, "Asha", std::nullopt};
    EXPECT_FALSE(to_json(ClientMessage{hello}).contains("follows_redirects"));
    hello.follows_redirects = true;
    EXPECT_EQ(to_json(ClientMessage{hello}).at("follows_redirects"), json(true));
    EXPECT_EQ(encode(ClientMessage{Hello{1, "Bo", std::nullopt, std::nullopt, true}}),
              R"({"follows_redirects":true,"name":"Bo","type":"hello","version":1})");
}

TEST(ProtoHelloFollowsRedirects, Decoded) {
    const auto hello_of = [](const std::string& text) {
        const auto decoded = decode_client(text);
        EXPECT_TRUE(decoded.ok()) << text;
        return decoded.ok() ? std::get<Hello>(*decoded.message) : Hello{};
    };
    EXPECT_TRUE(hello_of(R"({"type":"hello","version":1,"name":"Bo","follows_redirects":true})")
                    .follows_redirects);
    EXPECT_FALSE(hello_of(R"({"type":"hello","version":1,"name":"Bo","follows_redirects":false})")
                     .follows_redirects);
    EXPECT_FALSE(hello_of(R"({"type":"hello","version":1,"name":"Bo"})").follows_redirects);
    const Hello resume{kProtocolVersion, "Asha", std::string(32, 'a'), std::nullopt, true};
    const auto decoded = decode_client(encode(ClientMessage{resume}));
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(*decoded.message, ClientMessage{resume});
}

TEST(ProtoHelloFollowsRedirects, MustBeABoolean) {
    for (const char* value : {"1", "\"true\"", "null", "[]"}) {
        const std::string text =
            std::string(R"({"type":"hello","version":1,"name":"Bo","follows_redirects":)") + value +
            "}";
        const auto decoded = decode_client(text);
        EXPECT_FALSE(decoded.ok()) << value;
        EXPECT_EQ(decoded.ok() ? std::string() : decoded.error.code, "bad_field") << value;
    }
}

TEST(ProtoPausedResumed, WireShapes) {
    EXPECT_EQ(encode(ServerMessage{Event{PausedEvent{"store", "The match waits."}}}),
              R"({"kind":"paused","message":"The match waits.","reason":"store","type":"event"})");
    EXPECT_EQ(encode(ServerMessage{Event{ResumedEvent{}}}), R"({"kind":"resumed","type":"event"})");
}

TEST(ProtoPausedResumed, RoundTripAndKinds) {
    const Event paused = PausedEvent{"store", "The database does not answer; the match waits."};
    EXPECT_EQ(event_kind(paused), "paused");
    EXPECT_EQ(redirect_suite_decode(encode(ServerMessage{paused})), ServerMessage{paused});
    const Event resumed = ResumedEvent{};
    EXPECT_EQ(event_kind(resumed), "resumed");
    EXPECT_EQ(redirect_suite_decode(encode(ServerMessage{resumed})), ServerMessage{resumed});
    const ServerMessage empty_message{Event{PausedEvent{"store", ""}}};
    EXPECT_EQ(
        redirect_suite_decode(R"({"type":"event","kind":"paused","reason":"store","message":""})"),
        empty_message);
}

TEST(ProtoPausedResumed, PausedNeedsAReason) {
    EXPECT_EQ(redirect_suite_error(R"({"type":"event","kind":"paused","message":"x"})"),
              "bad_field");
    EXPECT_EQ(redirect_suite_error(R"({"type":"event","kind":"paused","reason":"","message":"x"})"),
              "bad_field");
    EXPECT_EQ(redirect_suite_error(R"({"type":"event","kind":"paused","reason":"store"})"),
              "bad_field");
    const json long_reason{
        {"type", "event"}, {"kind", "paused"}, {"reason", std::string(33, 's')}, {"message", ""}};
    EXPECT_EQ(redirect_suite_error(long_reason.dump()), "bad_field");
}

} // namespace
} // namespace carrom::proto
