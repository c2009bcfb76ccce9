#pragma once
// Wire "type" names in variant order, and the envelope checks and message decoding shared by
// both directions.

#include "carrom/proto/codec.hpp"
#include "carrom/proto/error.hpp"
#include "json_reader.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace carrom::proto::detail {

// Same order as the ClientMessage variant.
inline constexpr std::array<std::string_view, 10> kClientTypeNames{
    "hello", "create_room", "join_room", "quick_match", "aim",
    "shoot", "rematch",     "leave",     "ping",        "emote"};
// Same order as the ServerMessage variant.
inline constexpr std::array<std::string_view, 8> kServerTypeNames{
    "welcome", "room_state", "snapshot", "event", "shot_result", "error", "pong", "redirect"};
// Same order as the Event variant.
inline constexpr std::array<std::string_view, 15> kEventKindNames{
    "collision", "cushion",   "pocket",   "foul",           "queen",           "due",
    "turn",      "board_end", "game_end", "player_dropped", "player_returned", "aim",
    "emote",     "paused",    "resumed"};

template <std::size_t N>
std::optional<std::size_t> find_type(const std::array<std::string_view, N>& names,
                                     std::string_view name) {
    for (std::size_t i = 0; i < N; ++i) {
        if (names[i] == name) {
            return i;
        }
    }
    return std::nullopt;
}

struct TypeField {
    std::string name;
    Error error;
    bool ok() const { return error.code.empty(); }
};

// The "type" of a top-level value: not_object, missing_type (absent or not a string).
TypeField message_type(const nlohmann::json& value);
Error unknown_type_error(std::string_view name);

// The index-th alternative of Variant, default-constructed and then passed to fill; nullopt when
// index is not below the variant's size.
template <class Variant, std::size_t I = 0, class Fill>
std::optional<Variant> make_alternative(std::size_t index, Fill&& fill) {
    if constexpr (I < std::variant_size_v<Variant>) {
        if (index == I) {
            std::variant_alternative_t<I, Variant> value;
            fill(value);
            return Variant{std::move(value)};
        }
        return make_alternative<Variant, I + 1>(index, std::forward<Fill>(fill));
    } else {
        return std::nullopt;
    }
}

// A whole message of either direction as JSON: encode_body(alternative) and its "type".
template <class Message, std::size_t N, class EncodeBody>
nlohmann::json encode_message(const Message& message, const std::array<std::string_view, N>& names,
                              EncodeBody encode_body) {
    static_assert(N == std::variant_size_v<Message>, "one name per message type");
    nlohmann::json out = std::visit(encode_body, message);
    out["type"] = names[message.index()];
    return out;
}

// A whole message of either direction: the envelope's "type" names the alternative of Message
// (names lists them in variant order), whose fields decode_body(JsonReader&, Alternative&) reads
// in the Wire wording.
template <class Message, std::size_t N, class DecodeBody>
DecodedMessage<Message> decode_message(const nlohmann::json& value,
                                       const std::array<std::string_view, N>& names,
                                       DecodeBody decode_body) {
    static_assert(N == std::variant_size_v<Message>, "one name per message type");
    const TypeField type = message_type(value);
    if (!type.ok()) {
        return {std::nullopt, type.error};
    }
    const std::optional<std::size_t> index = find_type(names, type.name);
    if (!index) {
        return {std::nullopt, unknown_type_error(type.name)};
    }
    JsonReader reader(value, "", Wording::Wire);
    std::optional<Message> message =
        make_alternative<Message>(*index, [&](auto& body) { decode_body(reader, body); });
    if (!reader.ok()) {
        return {std::nullopt, *reader.error()};
    }
    return {std::move(message), {}};
}

} // namespace carrom::proto::detail
