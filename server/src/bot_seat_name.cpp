#include "bot_seat_name.hpp"

#include <array>

namespace carrom::server {

std::string bot_seat_name(proto::BotLevel level, int seat, int seats) {
    const std::string suffix = "(" + std::string(proto::to_string(level)) + ")";
    if (seats <= 2) {
        return "Bot " + suffix;
    }
    // One first name per seat of a four-seat table (seat 0 is the creator's, a bot there too in
    // a quick match filled by bots).
    static constexpr std::array<std::string_view, 4> kFirstNames{"Mira", "Ravi", "Kiran", "Dev"};
    const auto index = static_cast<std::size_t>(seat) % kFirstNames.size();
    return "Bot " + std::string(kFirstNames[index]) + " " + suffix;
}

proto::BotLevel bot_level_of_name(std::string_view name) {
    constexpr std::string_view kPrefix = "Bot ";
    proto::BotLevel level = proto::BotLevel::Medium;
    const auto open = name.rfind('(');
    if (!name.starts_with(kPrefix) || open == std::string_view::npos || !name.ends_with(')')) {
        return level;
    }
    const std::string_view text = name.substr(open + 1, name.size() - open - 2);
    if (!proto::parse(text, level)) {
        level = proto::BotLevel::Medium;
    }
    return level;
}

} // namespace carrom::server
