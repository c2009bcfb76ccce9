#pragma once
// The ratings the desktop client has read (GET /players/NAME answers) for its own player and the
// seats of its room, and what it shows from them: the lobby's line, each seat's rating, the
// change after a rated game. A name's *base* is its ratings as its game began (the first read in
// a room before the game is over, or the latest read when a rematch begins); the change is shown
// against it. Names as the server spells them in room_state. No I/O.

#include "carrom/client/player_record.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace carrom::client {

class RatingBook {
public:
    // A record read; as_base: it is also the base of its name (a read as its game begins).
    void record(const PlayerRecord& record, bool as_base);
    // A new game begins for these names: the latest read of each becomes its base.
    void game_starts(const std::vector<std::string>& names);
    // The lobby's line for name ("Rating: ICF 1532 (+14)"; "" without a rated game or a read).
    std::string lobby_line(const std::string& name) const;
    // The text beside a seat's name for rule_set ("1520?", "1532 (+14)"; "" for a guest, a bot,
    // a player without a rating in rule_set, or a name not read yet).
    std::string seat_text(const std::string& name, const std::string& rule_set) const;
    // name's rating in rule_set has more games than its base (a rated game changed it).
    bool changed(const std::string& name, const std::string& rule_set) const;
    // A read of name has come (a guest's too: it has no ratings).
    bool has(const std::string& name) const { return latest_.count(name) > 0; }

private:
    std::map<std::string, std::vector<RatingEntry>> latest_;
    std::map<std::string, std::vector<RatingEntry>> base_;
};

// What a row of the "My matches" list says about one of `me`'s matches.
struct MatchLine {
    std::string opponent; // the other seats' names, "Ravi" or "Ravi, Ann & Bo"
    std::string result;   // "won 25 : 11", "lost 11 : 25", "drawn 20 : 20", "playing", "unfinished"
    std::string date;     // the end's (or without one, its start's) date, "2026-11-28 17:40 UTC"
};

// me is compared with the match's players ignoring ASCII case (the server's names match so).
MatchLine match_line(const MatchEntry& match, const std::string& me);

} // namespace carrom::client
