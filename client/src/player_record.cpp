#include "carrom/client/player_record.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>

namespace carrom::client {

namespace player_api_json {

using nlohmann::json;

constexpr std::int64_t kMaxMs = std::int64_t{1} << 52; // Unix ms: exact in a double

// Reads fields of untrusted JSON; the first problem is kept ("ratings[0].label must be a
// string") and later reads give defaults.
class FieldReader {
public:
    const std::optional<std::string>& problem() const { return problem_; }

    const json* field(const json& object, const std::string& path, const std::string& key,
                      const char* expected) {
        if (problem_) {
            return nullptr;
        }
        const std::string at = path.empty() ? key : path + "." + key;
        if (!object.is_object() || !object.contains(key)) {
            problem_ = at + " is missing";
            return nullptr;
        }
        const json& value = object.at(key);
        const bool fits = std::string_view(expected) == "a string"        ? value.is_string()
                          : std::string_view(expected) == "a list"        ? value.is_array()
                          : std::string_view(expected) == "true or false" ? value.is_boolean()
                          : std::string_view(expected) == "an object"     ? value.is_object()
                                                                          : value.is_number();
        if (!fits) {
            problem_ = at + " must be " + expected;
            return nullptr;
        }
        return &value;
    }

    std::string text(const json& o, const std::string& path, const std::string& key) {
        const json* v = field(o, path, key, "a string");
        return v != nullptr ? v->get<std::string>() : std::string();
    }

    double number(const json& o, const std::string& path, const std::string& key) {
        const json* v = field(o, path, key, "a number");
        if (v == nullptr) {
            return 0.0;
        }
        const double d = v->get<double>();
        if (!std::isfinite(d)) {
            problem_ = (path.empty() ? key : path + "." + key) + " must be a finite number";
            return 0.0;
        }
        return d;
    }

    std::int64_t integer(const json& o, const std::string& path, const std::string& key,
                         std::int64_t max) {
        const double d = number(o, path, key);
        if (!problem_ && (d != std::floor(d) || d < 0.0 || d > static_cast<double>(max))) {
            problem_ = (path.empty() ? key : path + "." + key) + " must be an integer from 0 to " +
                       std::to_string(max);
            return 0;
        }
        return static_cast<std::int64_t>(d);
    }

    int count(const json& o, const std::string& path, const std::string& key) {
        return static_cast<int>(integer(o, path, key, 1000000000));
    }

    bool flag(const json& o, const std::string& path, const std::string& key) {
        const json* v = field(o, path, key, "true or false");
        return v != nullptr && v->get<bool>();
    }

    const json& list(const json& o, const std::string& path, const std::string& key) {
        static const json empty = json::array();
        const json* v = field(o, path, key, "a list");
        return v != nullptr ? *v : empty;
    }

    // A leaderboard row has no rule set of its own (with_rule_set false).
    RatingEntry rating(const json& o, const std::string& path, bool with_rule_set) {
        RatingEntry r;
        r.rule_set = with_rule_set ? text(o, path, "rule_set") : std::string();
        r.rating = number(o, path, "rating");
        r.deviation = number(o, path, "deviation");
        r.provisional = flag(o, path, "provisional");
        r.label = text(o, path, "label");
        r.games = count(o, path, "games");
        r.wins = count(o, path, "wins");
        r.losses = count(o, path, "losses");
        r.draws = count(o, path, "draws");
        return r;
    }

    MatchEntry match(const json& o, const std::string& path) {
        MatchEntry m;
        m.id = text(o, path, "id");
        m.rule_set = text(o, path, "rule_set");
        const json& players = list(o, path, "players");
        for (std::size_t i = 0; i < players.size() && !problem_; ++i) {
            if (!players[i].is_string()) {
                problem_ = path + ".players[" + std::to_string(i) + "] must be a string";
            } else {
                m.players.push_back(players[i].get<std::string>());
            }
        }
        m.teams = small_integers(list(o, path, "teams"), path + ".teams");
        m.scores = small_integers(list(o, path, "scores"), path + ".scores");
        m.created_ms = integer(o, path, "created_ms", kMaxMs);
        // An unfinished match has finished_ms and result null.
        if (o.is_object() && o.contains("finished_ms") && !o.at("finished_ms").is_null()) {
            m.finished_ms = integer(o, path, "finished_ms", kMaxMs);
        }
        if (o.is_object() && o.contains("result") && !o.at("result").is_null()) {
            const json* result = field(o, path, "result", "an object");
            if (result != nullptr) {
                const std::string at = path + ".result";
                if (result->contains("winner_team") && !result->at("winner_team").is_null()) {
                    m.winner_team = static_cast<int>(integer(*result, at, "winner_team", 3));
                }
                m.reason = text(*result, at, "reason");
            }
        }
        m.replay = text(o, path, "replay");
        if (!problem_ && m.replay.rfind("/matches/", 0) != 0) {
            problem_ = path + ".replay must be a path /matches/ID";
        }
        return m;
    }

    std::vector<int> small_integers(const json& values, const std::string& path) {
        std::vector<int> out;
        for (std::size_t i = 0; i < values.size() && !problem_; ++i) {
            const json& v = values[i];
            if (!v.is_number_integer() || v.get<std::int64_t>() < -1000000 ||
                v.get<std::int64_t>() > 1000000) {
                problem_ = path + "[" + std::to_string(i) + "] must be an integer";
            } else {
                out.push_back(v.get<int>());
            }
        }
        return out;
    }

private:
    std::optional<std::string> problem_;
};

std::optional<std::string> status_problem(const ApiAnswer& answer, const json& body) {
    if (answer.status == 0) {
        return answer.failure.empty() ? std::string("The server did not answer.") : answer.failure;
    }
    if (answer.status == 200) {
        return std::nullopt;
    }
    std::string code;
    std::string message;
    if (body.is_object() && body.contains("error") && body.at("error").is_object()) {
        const json& e = body.at("error");
        code =
            e.contains("code") && e.at("code").is_string() ? e.at("code").get<std::string>() : "";
        message = e.contains("message") && e.at("message").is_string()
                      ? e.at("message").get<std::string>()
                      : "";
    }
    if (answer.status == 429) {
        return std::string("The server has had too many requests from this address (429): try "
                           "again in a moment.");
    }
    if (keeps_no_players(answer)) {
        return std::string("This server keeps no players or ratings (it runs without a store).");
    }
    if (answer.status == 503) {
        return std::string("The server's store is busy (503): try again in a moment.");
    }
    std::string text = "The server answered " + std::to_string(answer.status);
    text += code.empty() ? "" : " " + code;
    if (!message.empty()) {
        text += ": " + message;
        if (text.back() != '.') {
            text += ".";
        }
        return text;
    }
    return text + ".";
}

std::string unreadable(const std::string& what, const std::string& problem) {
    return "The server sent " + what + " in a form this client does not read (" + problem + ").";
}

} // namespace player_api_json

bool keeps_no_players(const ApiAnswer& answer) {
    if (answer.status != 503) {
        return false;
    }
    const auto body = nlohmann::json::parse(answer.body, nullptr, false);
    if (!body.is_object() || !body.contains("error") || !body.at("error").is_object()) {
        return false;
    }
    const auto& error = body.at("error");
    return error.contains("code") && error.at("code") == "store_disabled";
}

std::variant<PlayerRecord, std::string> parse_player_answer(const std::string& name,
                                                            const ApiAnswer& answer) {
    using player_api_json::json;
    const json body = json::parse(answer.body, nullptr, false);
    if (answer.status == 404 && body.is_object() && body.contains("error") &&
        body["error"].is_object() && body["error"].value("code", "") == "unknown_player") {
        PlayerRecord empty;
        empty.name = name;
        return empty; // identified players appear once they say hello; guests never
    }
    if (auto problem = player_api_json::status_problem(answer, body)) {
        return *problem;
    }
    const std::string what = "the record of " + name;
    if (body.is_discarded()) {
        return player_api_json::unreadable(what, "not JSON");
    }
    player_api_json::FieldReader read;
    PlayerRecord record;
    record.name = read.text(body, "", "name");
    const json& ratings = read.list(body, "", "ratings");
    for (std::size_t i = 0; i < ratings.size() && !read.problem(); ++i) {
        record.ratings.push_back(
            read.rating(ratings[i], "ratings[" + std::to_string(i) + "]", true));
    }
    const json& matches = read.list(body, "", "matches");
    for (std::size_t i = 0; i < matches.size() && i < 20 && !read.problem(); ++i) {
        record.matches.push_back(read.match(matches[i], "matches[" + std::to_string(i) + "]"));
    }
    if (read.problem()) {
        return player_api_json::unreadable(what, *read.problem());
    }
    return record;
}

std::variant<Leaderboard, std::string> parse_leaderboard_answer(const ApiAnswer& answer) {
    using player_api_json::json;
    const json body = json::parse(answer.body, nullptr, false);
    // The web page's words for these two (rating_words.js, leaderboardView).
    if (answer.status == 429) {
        return std::string("Too many requests: try the leaderboard again in a few seconds.");
    }
    if (keeps_no_players(answer)) {
        return std::string("This server keeps no ratings, so it has no leaderboard.");
    }
    if (auto problem = player_api_json::status_problem(answer, body)) {
        return *problem;
    }
    if (body.is_discarded()) {
        return player_api_json::unreadable("the leaderboard", "not JSON");
    }
    player_api_json::FieldReader read;
    Leaderboard board;
    board.rule_set = read.text(body, "", "rule_set");
    const json& players = read.list(body, "", "players");
    for (std::size_t i = 0; i < players.size() && i < 100 && !read.problem(); ++i) {
        const std::string path = "players[" + std::to_string(i) + "]";
        LeaderboardRow row;
        row.rank = read.count(players[i], path, "rank");
        row.name = read.text(players[i], path, "name");
        row.rating = read.rating(players[i], path, false);
        row.rating.rule_set = board.rule_set;
        board.rows.push_back(std::move(row));
    }
    if (read.problem()) {
        return player_api_json::unreadable("the leaderboard", *read.problem());
    }
    return board;
}

std::optional<std::string> answer_problem(const ApiAnswer& answer) {
    return player_api_json::status_problem(
        answer, player_api_json::json::parse(answer.body, nullptr, false));
}

std::string player_path(std::string_view name) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string path = "/players/";
    for (const char c : name) {
        const auto byte = static_cast<unsigned char>(c);
        if (std::isalnum(byte) != 0 && byte < 128) {
            path += c;
        } else if (c == '-' || c == '.' || c == '_' || c == '~') {
            path += c;
        } else {
            path += '%';
            path += kHex[byte >> 4U];
            path += kHex[byte & 15U];
        }
    }
    return path;
}

} // namespace carrom::client
