#pragma once
// The answers of GET /players/NAME and GET /leaderboard (docs/protocol.md, "Players and
// leaderboard") as the desktop client reads them. Untrusted input: every field is checked for
// its type, and a wrong answer (not JSON, a field missing or of another type, an error status
// such as 404, 429 or 503) becomes one sentence for the view. No I/O.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::client {

// One rule set's rating of a player (a "ratings[]" entry or a leaderboard row's).
struct RatingEntry {
    std::string rule_set; // "icf", "seed", "freestyle", "discpool"
    double rating = 1500.0;
    double deviation = 350.0; // points
    bool provisional = true;  // deviation 110 or more
    std::string label;        // "1532", "1520?"
    int games = 0;
    int wins = 0;
    int losses = 0;
    int draws = 0;
    friend bool operator==(const RatingEntry&, const RatingEntry&) = default;
};

// One of a player's last matches ("matches[]").
struct MatchEntry {
    std::string id;
    std::string rule_set;
    std::vector<std::string> players; // in seat order
    std::vector<int> teams;           // each seat's team
    std::int64_t created_ms = 0;      // Unix ms
    std::int64_t finished_ms = 0;     // Unix ms; 0: not finished
    std::optional<int> winner_team;   // none: a draw or no result
    std::string reason;               // the result's reason ("" without a result)
    std::vector<int> scores;          // per team
    std::string replay;               // the journal's path on the same server, "/matches/ID"
    friend bool operator==(const MatchEntry&, const MatchEntry&) = default;
};

struct PlayerRecord {
    std::string name;
    std::vector<RatingEntry> ratings; // empty: no rated game (also a 404 unknown_player)
    std::vector<MatchEntry> matches;  // newest first, at most 20
};

struct LeaderboardRow {
    int rank = 0;
    std::string name;
    RatingEntry rating;
};

struct Leaderboard {
    std::string rule_set;
    std::vector<LeaderboardRow> rows; // best first
};

// An HTTP answer: the status and the body, or (status 0) the sentence why there is none (no
// connection, no answer in time).
struct ApiAnswer {
    unsigned status = 0;
    std::string body;
    std::string failure;
};

// The server keeps no players or ratings (503 with the error code store_disabled): asking it
// again changes nothing.
bool keeps_no_players(const ApiAnswer& answer);

// The sentence for an answer that is not a 200 (none came, 429, 503, 404, ...), or none.
std::optional<std::string> answer_problem(const ApiAnswer& answer);

// GET /players/NAME's answer. 404 unknown_player is a player without a rated game (an empty
// record named `name`); anything else but 200 is a sentence.
std::variant<PlayerRecord, std::string> parse_player_answer(const std::string& name,
                                                            const ApiAnswer& answer);

// GET /leaderboard's answer, or a sentence.
std::variant<Leaderboard, std::string> parse_leaderboard_answer(const ApiAnswer& answer);

// The path of GET /players/NAME with NAME percent-encoded (every byte but A-Z a-z 0-9 - . _ ~).
std::string player_path(std::string_view name);

} // namespace carrom::client
