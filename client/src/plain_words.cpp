#include "carrom/client/plain_words.hpp"

#include <array>
#include <utility>

namespace carrom::client {

std::string count_words(int count, std::string_view one, std::string_view many) {
    return std::to_string(count) + " " + std::string(count == 1 ? one : many);
}

std::string pocket_list(const std::vector<BodyKind>& kinds) {
    int black = 0;
    int white = 0;
    bool queen = false;
    bool striker = false;
    for (BodyKind k : kinds) {
        black += k == BodyKind::Black ? 1 : 0;
        white += k == BodyKind::White ? 1 : 0;
        queen = queen || k == BodyKind::Queen;
        striker = striker || k == BodyKind::Striker;
    }
    std::vector<std::string> parts;
    if (white > 0) {
        parts.push_back(count_words(white, "white coin", "white coins"));
    }
    if (black > 0) {
        parts.push_back(count_words(black, "black coin", "black coins"));
    }
    if (queen) {
        parts.emplace_back("the queen");
    }
    if (striker) {
        parts.emplace_back("the striker");
    }
    std::string out;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        if (i > 0) {
            out += i + 1 == parts.size() ? " and " : ", ";
        }
        out += parts[i];
    }
    return out.empty() ? "nothing" : out;
}

std::string queen_sentence(const proto::QueenInfo& queen, const std::string& seat_name) {
    switch (queen.state) {
    case proto::QueenState::Pending:
        return seat_name + " pocketed the queen: cover it with the next coin";
    case proto::QueenState::Covered:
        return seat_name + " covered the queen";
    case proto::QueenState::OnBoard:
        return "The queen is back on the centre";
    case proto::QueenState::None:
        break;
    }
    return "The queen moved";
}

std::string coins_left_text(const SeatCoins& coins) {
    std::string what;
    switch (coins.colour) {
    case proto::Colour::White:
        what = "white";
        break;
    case proto::Colour::Black:
        what = "black";
        break;
    case proto::Colour::None:
        what = coins.coins == 1 ? "coin" : "coins";
        break;
    }
    const std::string queen = coins.queen ? " + queen" : "";
    if (coins.coins == 0) {
        return coins.queen ? "only the queen left" : "no " + what + " left";
    }
    return std::to_string(coins.coins) + " " + what + queen + " left";
}

std::string error_sentence(const proto::Error& error) {
    namespace c = proto::code;
    static const std::array<std::pair<std::string_view, std::string_view>, 14> plain{{
        {c::kRoomNotFound, "There is no room with that code. Check the code and try again."},
        {c::kRoomFull, "That room is full. You can join it as a spectator."},
        {c::kNotYourTurn, "Wait for your turn."},
        {c::kStaleTurn, "That shot was for an earlier turn and was not played."},
        {c::kInMotion, "Wait until the pieces stop."},
        {c::kIllegalPlacement, "The striker cannot go there: it overlaps a piece."},
        {c::kIllegalShot, "That shot is not allowed."},
        {c::kSpectator, "Spectators cannot play."},
        {c::kVersionMismatch, "This client and the server speak different protocol versions. "
                              "Update the client."},
        {c::kBadToken, "Your seat could not be resumed: the grace period is over."},
        {c::kServerFull, "The server is full. Try again in a moment."},
        {c::kTooManyRooms, "The server has no room for another match. Try again later."},
        {c::kRateLimited, "Too many messages: slow down."},
        {c::kShuttingDown, "The server is shutting down."},
    }};
    for (const auto& [code, sentence] : plain) {
        if (error.code == code) {
            return std::string(sentence);
        }
    }
    return error.message.empty() ? "The server reported an error (" + error.code + ")."
                                 : error.message;
}

std::string rule_set_name(proto::RuleSet rule_set) {
    switch (rule_set) {
    case proto::RuleSet::Icf:
        return "ICF rules";
    case proto::RuleSet::Seed:
        return "Classic (seed) rules";
    case proto::RuleSet::Freestyle:
        return "Freestyle";
    case proto::RuleSet::DiscPool:
        return "Disc pool";
    }
    return "Unknown rules";
}

std::string target_words(proto::RuleSet rule_set, int target_points) {
    const std::string points = count_words(target_points, "point", "points");
    switch (rule_set) {
    case proto::RuleSet::Icf:
    case proto::RuleSet::Seed:
        return "to " + std::to_string(target_points) + ", scored at board end";
    case proto::RuleSet::Freestyle:
        return "first to " + points;
    case proto::RuleSet::DiscPool:
        break;
    }
    return "to " + points;
}

std::string foul_sentence(const std::string& name, const std::string& message) {
    return "Foul by " + name + ": " + message;
}

std::string foul_cost(const std::vector<BodyKind>& returned, int points) {
    std::vector<std::string> parts;
    if (!returned.empty()) {
        parts.push_back(pocket_list(returned) + " back to the centre");
    }
    if (points < 0) {
        parts.push_back(count_words(-points, "point", "points"));
    }
    if (parts.empty()) {
        return "";
    }
    return "Cost: " + (parts.size() == 1 ? parts[0] : parts[0] + " and " + parts[1]);
}

std::string stroke_points(int points) {
    if (points == 0) {
        return "";
    }
    return " (" + std::string(points > 0 ? "+" : "") + std::to_string(points) + ")";
}

std::string dues_sentence(const std::string& subject, bool plural, int owed) {
    const std::string coin = owed == 1 ? "the next coin " : "the next coins ";
    const std::string goes = owed == 1 ? " goes" : " go";
    return subject + (plural ? " owe " : " owes ") + count_words(owed, "due", "dues") + ": " +
           coin + (plural ? "they pocket" : subject + " pockets") + goes + " back to the centre";
}

std::string forfeit_sentence(const std::string& leaver, const std::string& reason,
                             const std::string& winner, bool plural) {
    const std::string what =
        reason == "left" ? " left the match: " : " did not come back in time: ";
    return leaver + what + winner + (plural ? " win" : " wins") + " by forfeit";
}

} // namespace carrom::client
