// Decoding failures that do not depend on the message type: size, JSON, envelope.
#include "carrom/proto/codec.hpp"

#include <gtest/gtest.h>

#include <string>

namespace carrom::proto {
namespace {

std::string client_error(std::string_view text, std::size_t max = kMaxClientMessageBytes) {
    const auto decoded = decode_client(text, max);
    return decoded.ok() ? std::string() : decoded.error.code;
}

std::string server_error(std::string_view text) {
    const auto decoded = decode_server(text);
    return decoded.ok() ? std::string() : decoded.error.code;
}

TEST(ProtoEnvelope, MalformedJson) {
    EXPECT_EQ(client_error(""), "malformed_json");
    EXPECT_EQ(client_error("{"), "malformed_json");
    EXPECT_EQ(client_error("{\"type\":\"ping\",\"nonce\":1"), "malformed_json");
    EXPECT_EQ(client_error("{'type':'ping'}"), "malformed_json");
    EXPECT_EQ(client_error("{\"type\":\"ping\",\"nonce\":1}{}"), "malformed_json");
    EXPECT_EQ(client_error("{\"type\":\"ping\",\"nonce\":01}"), "malformed_json");
    EXPECT_EQ(client_error("{\"type\":\"ping\",}"), "malformed_json");
    EXPECT_EQ(server_error("nonsense"), "malformed_json");
}

TEST(ProtoEnvelope, MalformedJsonMessageSaysWhere) {
    const auto decoded = decode_client("{\"a\":?}");
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.message, "The message is not valid JSON (error at byte 6).");
}

TEST(ProtoEnvelope, WhitespaceAroundAValidMessageIsFine) {
    EXPECT_EQ(client_error(" \n{\"type\":\"leave\"}\t "), "");
}

TEST(ProtoEnvelope, TopLevelMustBeAnObject) {
    EXPECT_EQ(client_error("[]"), "not_object");
    EXPECT_EQ(client_error("42"), "not_object");
    EXPECT_EQ(client_error("\"hello\""), "not_object");
    EXPECT_EQ(client_error("null"), "not_object");
    EXPECT_EQ(server_error("[1]"), "not_object");
}

TEST(ProtoEnvelope, TypeMustBeAString) {
    EXPECT_EQ(client_error("{}"), "missing_type");
    EXPECT_EQ(client_error("{\"type\":1}"), "missing_type");
    EXPECT_EQ(client_error("{\"type\":null}"), "missing_type");
    EXPECT_EQ(client_error("{\"Type\":\"ping\",\"nonce\":1}"), "missing_type");
}

TEST(ProtoEnvelope, UnknownTypes) {
    EXPECT_EQ(client_error("{\"type\":\"teleport\"}"), "unknown_type");
    EXPECT_EQ(client_error("{\"type\":\"PING\",\"nonce\":1}"), "unknown_type");
    EXPECT_EQ(client_error("{\"type\":\"\"}"), "unknown_type");
    // A server message sent to the server is unknown there, and vice versa.
    EXPECT_EQ(client_error("{\"type\":\"welcome\"}"), "unknown_type");
    EXPECT_EQ(server_error("{\"type\":\"shoot\"}"), "unknown_type");
}

TEST(ProtoEnvelope, UnknownTypeMessageIsShortAndPrintable) {
    const auto decoded = decode_client("{\"type\":\"" + std::string(100, 'x') + "\\u0001\"}");
    ASSERT_FALSE(decoded.ok());
    EXPECT_EQ(decoded.error.message, "Unknown message type '" + std::string(32, 'x') + "'.");
}

TEST(ProtoEnvelope, SizeLimitIsInclusive) {
    std::string text = "{\"type\":\"leave\"}";
    const std::size_t size = text.size();
    EXPECT_EQ(client_error(text, size), "");
    EXPECT_EQ(client_error(text, size - 1), "too_large");
}

TEST(ProtoEnvelope, DefaultClientLimitIsFourKiB) {
    std::string padded = "{\"type\":\"leave\",\"pad\":\"";
    padded += std::string(kMaxClientMessageBytes - padded.size() - 2, 'p');
    padded += "\"}";
    ASSERT_EQ(padded.size(), kMaxClientMessageBytes);
    EXPECT_EQ(client_error(padded), "");
    EXPECT_EQ(client_error(padded + " "), "too_large");
}

TEST(ProtoEnvelope, TooLargeIsCheckedBeforeParsing) {
    // Invalid JSON but too long: the size is reported, not the syntax.
    EXPECT_EQ(client_error(std::string(5000, '['), 4096), "too_large");
}

TEST(ProtoEnvelope, DeepNestingInsideTheLimitIsHarmless) {
    std::string deep =
        "{\"type\":\"leave\",\"x\":" + std::string(2000, '[') + std::string(2000, ']') + "}";
    EXPECT_EQ(client_error(deep), "");
}

TEST(ProtoEnvelope, ErrorTextIsAnErrorMessage) {
    const std::string text = encode_error("rate_limited", "Slow down.");
    EXPECT_EQ(text, R"({"code":"rate_limited","message":"Slow down.","type":"error"})");
    const auto decoded = decode_server(text);
    ASSERT_TRUE(decoded.ok());
    EXPECT_EQ(std::get<Error>(*decoded.message), (Error{"rate_limited", "Slow down."}));
}

TEST(ProtoEnvelope, EncodingNeverThrowsOnInvalidUtf8) {
    const std::string text = encode_error("internal", "bad \xff byte");
    EXPECT_TRUE(decode_server(text).ok()) << text;
}

TEST(ProtoEnvelope, Quantise) {
    EXPECT_EQ(quantise(123.456), 123.46);
    EXPECT_EQ(quantise(-0.004), 0.0);
    EXPECT_EQ(quantise(-1.236), -1.24);
    EXPECT_EQ(quantise(300.0), 300.0);
}

} // namespace
} // namespace carrom::proto
