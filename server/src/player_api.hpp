#pragma once
// Private to server/src: the players' part of the match API (docs/protocol.md, "Players and
// leaderboard"): GET /players/NAME (an identified player's ratings, record and last matches)
// and GET /leaderboard?rule_set=R&limit=N (established ratings, best first, with rank). Answered
// like the match API: on the MatchApiReader's thread, rate-limited per address. Boost-free.

#include "match_api.hpp"

#include <string_view>
#include <utility>
#include <vector>

namespace carrom::server {

inline constexpr int kPlayerMatchListLimit = 20; // the last matches GET /players/NAME lists
inline constexpr int kDefaultLeaderboardLimit = 50;
inline constexpr int kMaxLeaderboardLimit = store::kMaxLeaderboardRows;

// A query's key=value pairs in order (views into query; values still percent-encoded); the
// match API's and these endpoints' parameters.
std::vector<std::pair<std::string_view, std::string_view>> query_params(std::string_view query);

// GET /players: {"kept": true} when this server keeps players and ratings (a store), else
// {"kept": false}; 200 either way, so that a page can ask before reading a player.
inline constexpr std::string_view kPlayersKeptPath = "/players";
MatchApiAnswer answer_players_kept(bool kept);

// "/players", "/players/..." and "/leaderboard".
bool is_player_api_path(std::string_view path);

MatchApiAnswer answer_player_api(store::MatchStore& store, std::string_view path,
                                 std::string_view query);

} // namespace carrom::server
