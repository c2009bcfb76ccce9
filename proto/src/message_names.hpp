#pragma once
// Wire "type" names in variant order, and the envelope checks shared by both directions.

#include "carrom/proto/error.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace carrom::proto::detail {

// Same order as the ClientMessage variant.
inline constexpr std::array<std::string_view, 9> kClientTypeNames{
    "hello", "create_room", "join_room", "quick_match", "aim", "shoot", "rematch", "leave", "ping"};
// Same order as the ServerMessage variant.
inline constexpr std::array<std::string_view, 7> kServerTypeNames{
    "welcome", "room_state", "snapshot", "event", "shot_result", "error", "pong"};
// Same order as the Event variant.
inline constexpr std::array<std::string_view, 12> kEventKindNames{
    "collision", "cushion",   "pocket",   "foul",           "queen",           "due",
    "turn",      "board_end", "game_end", "player_dropped", "player_returned", "aim"};

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

} // namespace carrom::proto::detail
