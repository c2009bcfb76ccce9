#include "player_api.hpp"

#include "player_name_key.hpp"

#include "carrom/proto/journal.hpp"
#include "carrom/proto/types.hpp"
#include "carrom/ratings/rating.hpp"

namespace carrom::server {

namespace {

using Json = nlohmann::json;

constexpr std::string_view kPlayersPrefix = "/players/";
constexpr std::chrono::milliseconds kUnknownPlayerFlushTimeout{500};

Json rating_json(const store::PlayerRating& r) {
    return {{"rule_set", std::string(rules::to_string(r.rule_set))},
            {"rating", r.rating.rating},
            {"deviation", r.rating.deviation},
            {"volatility", r.rating.volatility},
            {"provisional", ratings::is_provisional(r.rating)},
            {"label", ratings::rating_label(r.rating)},
            {"games", r.games},
            {"wins", r.wins},
            {"losses", r.losses},
            {"draws", r.draws},
            {"last_game_ms", r.last_game_ms}};
}

MatchApiAnswer answer_player(store::MatchStore& store, std::string_view raw_name,
                             std::string_view query) {
    if (!query.empty()) {
        return match_api_error(400, match_api_code::kBadQuery, "/players/NAME takes no query.");
    }
    const std::optional<std::string> name = url_decode(raw_name);
    const std::optional<std::string> name_key =
        name && proto::is_player_name(*name) ? player_name_key(*name) : std::nullopt;
    if (!name_key) {
        return match_api_error(400, match_api_code::kBadPlayerName,
                               "A player name is 1 to 24 bytes of UTF-8 with no control "
                               "characters, percent-encoded in the path.");
    }
    auto player = store.find_player(*name_key);
    if (player.ok() && !player.value) {
        // A hello queues its player's identity: one who said hello a moment ago is read once
        // the writes queued until now are written (bounded; a name nobody holds waits for the
        // queue, not for this timeout, when the store keeps up).
        (void)store.flush(kUnknownPlayerFlushTimeout);
        player = store.find_player(*name_key);
    }
    if (!player.ok()) {
        return match_api_error(500, match_api_code::kStoreError, player.error->message);
    }
    if (!player.value) {
        return match_api_error(404, match_api_code::kUnknownPlayer,
                               "No identified player is called " + *name + ".");
    }
    auto rated = store.player_ratings(player.value->key_hash);
    auto matches = store.recent_matches(player.value->name, kPlayerMatchListLimit);
    if (!rated.ok() || !matches.ok()) {
        return match_api_error(500, match_api_code::kStoreError,
                               (rated.ok() ? matches.error : rated.error)->message);
    }
    Json ratings_list = Json::array();
    for (const auto& r : rated.value) {
        ratings_list.push_back(rating_json(r));
    }
    Json match_list = Json::array();
    for (const auto& m : matches.value) {
        Json line = match_listing_json(m);
        line["replay"] = "/matches/" + m.id;
        match_list.push_back(std::move(line));
    }
    return {200, Json{{"name", player.value->name},
                      {"created_ms", player.value->created_ms},
                      {"ratings", ratings_list},
                      {"matches", match_list}}
                     .dump()};
}

MatchApiAnswer answer_leaderboard(store::MatchStore& store, std::string_view query) {
    rules::RuleSet rule_set = rules::RuleSet::Icf;
    int limit = kDefaultLeaderboardLimit;
    for (const auto& [key, raw] : query_params(query)) {
        if (key == "rule_set") {
            if (!rules::parse_rule_set(raw, rule_set)) {
                return match_api_error(400, match_api_code::kBadQuery,
                                       "rule_set must be icf, seed, freestyle or discpool.");
            }
        } else if (key == "limit") {
            if (!parse_query_int(raw, 1, kMaxLeaderboardLimit, limit)) {
                return match_api_error(400, match_api_code::kBadQuery,
                                       "limit must be an integer from 1 to 100.");
            }
        } else {
            return match_api_error(400, match_api_code::kBadQuery,
                                   "Unknown query parameter; use rule_set and limit.");
        }
    }
    auto board = store.leaderboard(rule_set, limit);
    if (!board.ok()) {
        return match_api_error(500, match_api_code::kStoreError, board.error->message);
    }
    Json rows = Json::array();
    int rank = 0;
    for (const auto& row : board.value) {
        Json line = rating_json(row.rating);
        line.erase("rule_set");
        line["rank"] = ++rank;
        line["name"] = row.name;
        rows.push_back(std::move(line));
    }
    return {200,
            Json{{"rule_set", std::string(rules::to_string(rule_set))}, {"players", rows}}.dump()};
}

} // namespace

bool is_player_api_path(std::string_view path) {
    return path == "/leaderboard" || path == kPlayersKeptPath || path.starts_with(kPlayersPrefix);
}

MatchApiAnswer answer_players_kept(bool kept) {
    return {200, Json{{"kept", kept}}.dump()};
}

MatchApiAnswer answer_player_api(store::MatchStore& store, std::string_view path,
                                 std::string_view query) {
    if (path == "/leaderboard") {
        return answer_leaderboard(store, query);
    }
    return answer_player(store, path.substr(kPlayersPrefix.size()), query);
}

} // namespace carrom::server
