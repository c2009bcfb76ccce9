#include "match_api.hpp"

#include "hex_digit.hpp"
#include "player_api.hpp"

#include "carrom/proto/journal_json.hpp"
#include "carrom/proto/match_json.hpp"
#include "carrom/proto/types.hpp"

#include <nlohmann/json.hpp>

#include <charconv>
#include <optional>
#include <utility>
#include <vector>

namespace carrom::server {

namespace {

using Json = nlohmann::json;

MatchApiAnswer error(int status, std::string_view code, std::string message) {
    return match_api_error(status, code, std::move(message));
}

MatchApiAnswer answer_journal(store::MatchStore& store, std::string_view id) {
    if (!proto::is_match_id(id)) {
        return error(400, match_api_code::kBadMatchId,
                     "A match id is 1 to 64 characters of 0-9, A-Z, a-z, '_' and '-'.");
    }
    auto loaded = store.journal(std::string(id));
    if (!loaded.ok()) {
        return error(500, match_api_code::kStoreError, loaded.error->message);
    }
    if (!loaded.value) {
        return error(404, match_api_code::kUnknownMatch,
                     "There is no match " + std::string(id) + ".");
    }
    return {200, proto::journal_to_json(*loaded.value).dump()};
}

MatchApiAnswer answer_list(store::MatchStore& store, std::string_view query) {
    std::optional<std::string> player;
    int limit = kDefaultMatchListLimit;
    for (const auto& [key, raw] : query_params(query)) {
        if (key == "player") {
            player = url_decode(raw);
            if (!player || !proto::is_player_name(*player)) {
                return error(400, match_api_code::kBadQuery,
                             "player must be a player name (1 to 24 bytes of UTF-8, no control "
                             "characters).");
            }
        } else if (key == "limit") {
            if (!parse_query_int(raw, 1, kMaxMatchListLimit, limit)) {
                return error(400, match_api_code::kBadQuery,
                             "limit must be an integer from 1 to 100.");
            }
        } else {
            return error(400, match_api_code::kBadQuery,
                         "Unknown query parameter; use player and limit.");
        }
    }
    if (!player) {
        return error(400, match_api_code::kBadQuery, "player is required: /matches?player=NAME.");
    }
    auto loaded = store.recent_matches(*player, limit);
    if (!loaded.ok()) {
        return error(500, match_api_code::kStoreError, loaded.error->message);
    }
    Json list = Json::array();
    for (const auto& m : loaded.value) {
        list.push_back(match_listing_json(m));
    }
    return {200,
            Json{{"format", proto::kJournalFormat}, {"player", *player}, {"matches", list}}.dump()};
}

} // namespace

std::optional<std::string> url_decode(std::string_view text) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '+') {
            out.push_back(' ');
        } else if (c == '%') {
            if (i + 2 >= text.size()) {
                return std::nullopt;
            }
            const int hi = hex_value(text[i + 1]);
            const int lo = hex_value(text[i + 2]);
            if (hi < 0 || lo < 0) {
                return std::nullopt;
            }
            out.push_back(static_cast<char>(hi * 16 + lo));
            i += 2;
        } else {
            out.push_back(c);
        }
    }
    return out;
}

nlohmann::json match_listing_json(const store::MatchListing& m) {
    return {{"id", m.id},
            {"room", m.room_code},
            {"rule_set", std::string(rules::to_string(m.rule_set))},
            {"players", m.players},
            {"teams", m.teams},
            {"created_ms", m.created_ms},
            {"finished_ms", m.finished_ms ? Json(*m.finished_ms) : Json(nullptr)},
            {"result", m.result ? proto::game_result_to_json(*m.result) : Json(nullptr)},
            {"scores", m.scores},
            // The web client's replay page for it, relative to this server (docs/web.md).
            {"replay", "/#/replay/" + m.id}};
}

std::vector<std::pair<std::string_view, std::string_view>> query_params(std::string_view query) {
    std::vector<std::pair<std::string_view, std::string_view>> params;
    while (!query.empty()) {
        const auto amp = query.find('&');
        const std::string_view pair = query.substr(0, amp);
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
        const auto eq = pair.find('=');
        params.emplace_back(pair.substr(0, eq), eq == std::string_view::npos ? std::string_view{}
                                                                             : pair.substr(eq + 1));
    }
    return params;
}

bool parse_query_int(std::string_view raw, int min, int max, int& out) {
    int value = 0;
    const auto [end, ec] = std::from_chars(raw.data(), raw.data() + raw.size(), value);
    if (ec != std::errc{} || end != raw.data() + raw.size() || value < min || value > max) {
        return false;
    }
    out = value;
    return true;
}

MatchApiAnswer match_api_error(int status, std::string_view code, std::string message) {
    return {status,
            Json{{"error", {{"code", std::string(code)}, {"message", std::move(message)}}}}.dump()};
}

bool is_match_api_target(std::string_view target) {
    const std::string_view path = target.substr(0, target.find('?'));
    return path == "/matches" || path.starts_with("/matches/") || is_player_api_path(path);
}

MatchApiAnswer answer_match_api(store::MatchStore* store, std::string_view target) {
    if (target == kPlayersKeptPath) {
        return answer_players_kept(store != nullptr);
    }
    if (store == nullptr) {
        return error(503, match_api_code::kStoreDisabled,
                     "This server keeps no matches (carrom-server --data none).");
    }
    const auto q = target.find('?');
    const std::string_view path = target.substr(0, q);
    const std::string_view query =
        q == std::string_view::npos ? std::string_view{} : target.substr(q + 1);
    if (path == "/matches") {
        return answer_list(*store, query);
    }
    if (is_player_api_path(path)) {
        return answer_player_api(*store, path, query);
    }
    if (!query.empty()) {
        return error(400, match_api_code::kBadQuery, "/matches/ID takes no query.");
    }
    return answer_journal(*store, path.substr(std::string_view("/matches/").size()));
}

} // namespace carrom::server
