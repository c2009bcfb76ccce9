// The "emote" client message and the "emote" event: wire shapes, every name, and the exact error
// of every malformed case.
#include "carrom/proto/codec.hpp"
#include "carrom/proto/json_codec.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

// The decoded client message's error code ("" on success).
std::string emote_client_error(const std::string& text) {
    const auto decoded = decode_client(text);
    return decoded.ok() ? std::string() : decoded.error.code;
}
// The decoded server message's error code ("" on success).
std::string emote_server_error(const std::string& text) {
    const auto decoded = decode_server(text);
    return decoded.ok() ? std::string() : decoded.error.code;
}

TEST(ProtoEmote, ClientWireShape) {
    EXPECT_EQ(encode(ClientMessage{EmoteMessage{Emote::GoodGame}}),
              R"({"emote":"good_game","type":"emote"})");
}

TEST(ProtoEmote, EventWireShape) {
    EXPECT_EQ(encode(ServerMessage{Event{EmoteEvent{1, Emote::Oops}}}),
              R"({"emote":"oops","kind":"emote","seat":1,"type":"event"})");
}

TEST(ProtoEmote, EveryNameDecodesToItsEmote) {
    const std::pair<const char*, Emote> cases[] = {{"nice_shot", Emote::NiceShot},
                                                   {"good_game", Emote::GoodGame},
                                                   {"well_played", Emote::WellPlayed},
                                                   {"thanks", Emote::Thanks},
                                                   {"good_luck", Emote::GoodLuck},
                                                   {"oops", Emote::Oops},
                                                   {"wow", Emote::Wow},
                                                   {"sorry", Emote::Sorry}};
    for (const auto& [name, emote] : cases) {
        const auto decoded =
            decode_client(std::string(R"({"type":"emote","emote":")") + name + "\"}");
        ASSERT_TRUE(decoded.ok()) << name;
        EXPECT_EQ(std::get<EmoteMessage>(*decoded.message).emote, emote) << name;
        const ServerMessage event{Event{EmoteEvent{3, emote}}};
        EXPECT_EQ(decode_server(encode(event)).message, event) << name;
    }
}

TEST(ProtoEmote, ClientRejectsAMissingEmote) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote"})"), "bad_field");
}

TEST(ProtoEmote, ClientRejectsAnUnknownName) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":"hurry_up"})"), "bad_field");
}

TEST(ProtoEmote, ClientRejectsFreeText) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":"you are slow"})"), "bad_field");
}

TEST(ProtoEmote, ClientRejectsAnEmptyName) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":""})"), "bad_field");
}

TEST(ProtoEmote, ClientNamesAreCaseSensitive) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":"Nice_Shot"})"), "bad_field");
}

TEST(ProtoEmote, ClientRejectsANumber) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":0})"), "bad_field");
}

TEST(ProtoEmote, ClientRejectsNull) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":null})"), "bad_field");
}

TEST(ProtoEmote, ClientRejectsAnArray) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":["wow"]})"), "bad_field");
}

TEST(ProtoEmote, ClientErrorNamesTheField) {
    const auto decoded = decode_client(R"({"type":"emote","emote":"boo"})");
    ASSERT_FALSE(decoded.ok());
    EXPECT_NE(decoded.error.message.find("emote"), std::string::npos) << decoded.error.message;
}

TEST(ProtoEmote, ClientIgnoresUnknownFields) {
    EXPECT_EQ(emote_client_error(R"({"type":"emote","emote":"wow","text":"hi"})"), "");
}

TEST(ProtoEmote, EventRejectsASeatOutOfRange) {
    EXPECT_EQ(emote_server_error(R"({"type":"event","kind":"emote","seat":4,"emote":"wow"})"),
              "bad_field");
    EXPECT_EQ(emote_server_error(R"({"type":"event","kind":"emote","seat":-1,"emote":"wow"})"),
              "bad_field");
}

TEST(ProtoEmote, EventRejectsAMissingSeat) {
    EXPECT_EQ(emote_server_error(R"({"type":"event","kind":"emote","emote":"wow"})"), "bad_field");
}

TEST(ProtoEmote, EventRejectsAnUnknownName) {
    EXPECT_EQ(emote_server_error(R"({"type":"event","kind":"emote","seat":0,"emote":"boo"})"),
              "bad_field");
}

TEST(ProtoEmote, EmoteTooFastIsItsOwnCode) {
    EXPECT_EQ(code::kEmoteTooFast, "emote_too_fast");
    EXPECT_NE(code::kEmoteTooFast, code::kRateLimited);
}

} // namespace
} // namespace carrom::proto
