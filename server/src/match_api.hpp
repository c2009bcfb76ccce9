#pragma once
// Private to server/src: the HTTP API of the match store (docs/matches.md, "Match API"):
// GET /matches/ID (a journal as JSON) and GET /matches?player=NAME&limit=N (a player's recent
// matches). Boost-free: the HTTP session hands it the request target and writes its answer.
// Reads block on the store (SQLite: a read on its reader connection): carrom-server calls it on
// the MatchApiReader's thread (match_api_reader.hpp), never on an I/O thread.

#include "store/match_store.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <string_view>

namespace carrom::server {

namespace match_api_code {
inline constexpr std::string_view kStoreDisabled = "store_disabled";  // 503: --data none
inline constexpr std::string_view kBadMatchId = "bad_match_id";       // 400
inline constexpr std::string_view kBadQuery = "bad_query";            // 400
inline constexpr std::string_view kUnknownMatch = "unknown_match";    // 404
inline constexpr std::string_view kBadPlayerName = "bad_player_name"; // 400: /players/NAME
inline constexpr std::string_view kUnknownPlayer = "unknown_player";  // 404: no such identity
inline constexpr std::string_view kStoreError = "store_error";        // 500: the read failed
inline constexpr std::string_view kStoreBusy = "store_busy";          // 503: too many reads wait
inline constexpr std::string_view kRateLimited = "rate_limited";      // 429: per-address limit
} // namespace match_api_code

inline constexpr int kDefaultMatchListLimit = 20;
inline constexpr int kMaxMatchListLimit = 100;

struct MatchApiAnswer {
    int status = 200;
    std::string body; // JSON (application/json)
};

// An error answer: {"error": {"code": code, "message": message}}.
MatchApiAnswer match_api_error(int status, std::string_view code, std::string message);

// Percent-decoding of a query value or path segment ('+' is a space); none when malformed.
std::optional<std::string> url_decode(std::string_view text);

// A decimal integer in [min, max] (the whole of raw) into out; false (out unchanged) otherwise.
bool parse_query_int(std::string_view raw, int min, int max, int& out);

// A line of a match list: {"id", "room", "rule_set", "players", "teams", "created_ms",
// "finished_ms", "result", "scores"} (docs/matches.md).
nlohmann::json match_listing_json(const store::MatchListing& listing);

// True for the paths this API answers: "/matches" (with a query), "/matches/...", and the
// players' ("/players/...", "/leaderboard": player_api.hpp).
bool is_match_api_target(std::string_view target);

// The answer to a GET of target (the request target: path and query). store may be null.
MatchApiAnswer answer_match_api(store::MatchStore* store, std::string_view target);

} // namespace carrom::server
