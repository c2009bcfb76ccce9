// Text <-> message: size limit, JSON parsing without escaping exceptions, envelope checks.
#include "carrom/proto/codec.hpp"

#include "carrom/proto/json_codec.hpp"

#include "message_names.hpp"

#include <cmath>
#include <exception>

namespace carrom::proto {

using nlohmann::json;

namespace detail {

TypeField message_type(const json& value) {
    if (!value.is_object()) {
        return {{}, Error{std::string(code::kNotObject), "A message must be a JSON object."}};
    }
    const auto it = value.find("type");
    if (it == value.end() || !it->is_string()) {
        return {
            {},
            Error{std::string(code::kMissingType), "A message must have a string field 'type'."}};
    }
    return {it->get<std::string>(), {}};
}

Error unknown_type_error(std::string_view name) {
    constexpr std::size_t kShown = 32;
    std::string shown(name.substr(0, kShown));
    for (char& c : shown) {
        if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) {
            c = '?';
        }
    }
    return Error{std::string(code::kUnknownType), "Unknown message type '" + shown + "'."};
}

} // namespace detail

namespace {

struct Parsed {
    json value;
    Error error;
};

// Parses untrusted text; every failure becomes an Error.
Parsed parse_text(std::string_view text, std::size_t max_bytes) {
    if (text.size() > max_bytes) {
        return {{},
                Error{std::string(code::kTooLarge),
                      "The message is " + std::to_string(text.size()) + " bytes; the limit is " +
                          std::to_string(max_bytes) + "."}};
    }
    // nlohmann's lexer reads a NUL byte as the end of the input, so text after one would be
    // ignored; valid JSON never holds a raw NUL (not even inside a string).
    if (const auto nul = text.find('\0'); nul != std::string_view::npos) {
        return {{},
                Error{std::string(code::kMalformedJson),
                      "The message is not valid JSON (a NUL byte at byte " + std::to_string(nul) +
                          ")."}};
    }
    try {
        return {json::parse(text.begin(), text.end()), {}};
    } catch (const json::parse_error& e) {
        return {
            {},
            Error{std::string(code::kMalformedJson),
                  "The message is not valid JSON (error at byte " + std::to_string(e.byte) + ")."}};
    } catch (const std::exception&) {
        return {{}, Error{std::string(code::kMalformedJson), "The message could not be parsed."}};
    }
}

std::string dump(const json& value) {
    return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

} // namespace

std::string encode(const ClientMessage& message) {
    return dump(to_json(message));
}
std::string encode(const ServerMessage& message) {
    return dump(to_json(message));
}

DecodedMessage<ClientMessage> decode_client(std::string_view text, std::size_t max_bytes) {
    Parsed parsed = parse_text(text, max_bytes);
    if (!parsed.error.code.empty()) {
        return {std::nullopt, std::move(parsed.error)};
    }
    return client_from_json(parsed.value);
}

DecodedMessage<ServerMessage> decode_server(std::string_view text, std::size_t max_bytes) {
    Parsed parsed = parse_text(text, max_bytes);
    if (!parsed.error.code.empty()) {
        return {std::nullopt, std::move(parsed.error)};
    }
    return server_from_json(parsed.value);
}

std::string encode_error(std::string_view code, std::string_view message) {
    json out{{"type", "error"}, {"code", code}, {"message", message}};
    return dump(out);
}

double quantise(double value) {
    return std::round(value * 100.0) / 100.0;
}

} // namespace carrom::proto
