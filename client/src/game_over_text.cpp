#include "carrom/client/game_over_text.hpp"

namespace carrom::client {
namespace {

// Results name teams: in singles a team is one seat (its number is the seat), in doubles the two
// partners (team t: seats t and t + 2).
bool doubles(const MatchView& v) {
    return v.seats.size() == 4;
}

// The other team of a two-team room (the one that did not win), -1 if there is none.
int other_team(const MatchView& v, int team) {
    if (team < 0 || (v.seats.size() != 2 && v.seats.size() != 4)) {
        return -1;
    }
    return 1 - team;
}

bool ours(const MatchView& v, int team) {
    return team >= 0 && team == team_of(v, v.you);
}

// The team's players: "Ana", or "Ana & Cy" (the names they had when the game ended).
std::string name(const MatchView& v, int team) {
    return doubles(v) ? team_name(v, team) : player_name_at_end(v, team);
}

// To start a sentence: "You", "You & Cy" (our partner named), or the team's players.
std::string subject(const MatchView& v, int team) {
    if (!ours(v, team)) {
        return name(v, team);
    }
    const int partner = partner_of(v, v.you);
    return partner >= 0 ? "You & " + player_name_at_end(v, partner) : std::string("You");
}

// "have" for you or a pair, "has" for one other player.
std::string has(const MatchView& v, int team) {
    return ours(v, team) || doubles(v) ? "have" : "has";
}

// "you have" / "Ana has" / "Ana & Cy have": who leads on points, or that the scores are level.
std::string who_leads(const MatchView& v, int winner) {
    if (winner < 0) {
        return "the scores are level";
    }
    std::string who = subject(v, winner);
    if (ours(v, winner)) {
        who[0] = 'y'; // mid-sentence: "you", "you & Cy"
    }
    return who + " " + has(v, winner) + " more points";
}

std::string cleared_reason(const MatchView& v, int winner) {
    switch (v.rule_set) {
    case proto::RuleSet::Seed:
        return "A colour is off the board and " + who_leads(v, winner) + ".";
    case proto::RuleSet::Freestyle:
        return "No coins are left on the board and " + who_leads(v, winner) + ".";
    case proto::RuleSet::DiscPool:
        if (winner < 0) {
            return "The coins are off the board.";
        }
        if (ours(v, winner)) {
            return doubles(v) ? std::string("All your team's coins are off the board.")
                              : std::string("All your coins are off the board.");
        }
        return "All of " + name(v, winner) + "'s coins are off the board.";
    case proto::RuleSet::Icf:
        break;
    }
    return winner < 0 ? "The board is cleared." : subject(v, winner) + " cleared the board.";
}

// Why the losing team lost when it was not on points: in doubles one of its players did it.
std::string lost_reason(const MatchView& v, int loser, const std::string& reason) {
    if (doubles(v)) {
        const std::string who = ours(v, loser) ? "your team" : name(v, loser);
        if (reason == "clock") {
            return "A player of " + who + " let the shot clock run out three times in a row.";
        }
        if (reason == "forfeit") {
            return "A player of " + who + " lost the connection and did not come back in time.";
        }
        return "A player of " + who + " left the game.";
    }
    if (reason == "clock") {
        return subject(v, loser) + " let the shot clock run out three times in a row.";
    }
    if (reason == "forfeit") {
        return subject(v, loser) + " lost the connection and did not come back in time.";
    }
    return subject(v, loser) + " left the game.";
}

std::string reason_sentence(const MatchView& v, const GameResult& r) {
    const int loser = other_team(v, r.winner);
    if (r.reason == "score" && r.winner >= 0) {
        return subject(v, r.winner) + " reached " + std::to_string(v.options.target_points) +
               " points.";
    }
    if (r.reason == "boards") {
        const std::string played =
            v.options.boards == 1
                ? std::string("The board is played")
                : "All " + std::to_string(v.options.boards) + " boards are played";
        return played + " and " + who_leads(v, r.winner) + ".";
    }
    if (r.reason == "cleared") {
        return cleared_reason(v, r.winner);
    }
    if (loser >= 0 && (r.reason == "clock" || r.reason == "forfeit" || r.reason == "left")) {
        return lost_reason(v, loser, r.reason);
    }
    if (r.reason.empty()) {
        return "The game is over.";
    }
    return "The game is over (" + r.reason + ").";
}

std::string title(const MatchView& v, int winner) {
    if (winner < 0) {
        return "A draw";
    }
    if (doubles(v)) {
        return subject(v, winner) + " win";
    }
    if (ours(v, winner)) {
        return "You won!";
    }
    return v.you >= 0 ? "You lost" : name(v, winner) + " won";
}

// Our team first (seat 0's for a spectator); a team's score is any of its seats' entry.
std::string score_line(const MatchView& v, const GameResult& r) {
    std::string out = "Final score: ";
    const int n = static_cast<int>(r.scores.size());
    const int teams = doubles(v) ? 2 : n;
    const int first = v.you >= 0 && v.you < n ? team_of(v, v.you) : 0;
    for (int i = 0; i < teams; ++i) {
        const int team = (first + i) % teams;
        const int seat = team; // a team's first seat has the team's number
        if (seat >= n) {
            continue;
        }
        out += (i > 0 ? ", " : "") + name(v, team) + " " +
               std::to_string(r.scores[static_cast<std::size_t>(seat)]);
    }
    return out;
}

// A seat other than ours is empty: its player left after the game (no rematch until someone takes
// the seat; the server starts one only when every seat asks).
bool seat_empty(const MatchView& v) {
    for (int seat = 0; seat < static_cast<int>(v.seats.size()); ++seat) {
        if (seat != v.you && !v.seats[static_cast<std::size_t>(seat)].occupied) {
            return true;
        }
    }
    return false;
}

std::string rematch_wait(const MatchView& v) {
    int other_humans = 0;
    int other = -1;
    for (int seat = 0; seat < static_cast<int>(v.seats.size()); ++seat) {
        const SeatView& s = v.seats[static_cast<std::size_t>(seat)];
        if (seat != v.you && s.occupied && (!s.bot || !doubles(v))) {
            ++other_humans;
            other = seat;
        }
    }
    if (other_humans == 1) {
        return "Waiting for " + seat_name(v, other) + " to agree to a rematch";
    }
    return "Waiting for the other players to agree to a rematch";
}

} // namespace

GameOverText game_over_text(const MatchView& view, bool rematch_asked) {
    GameOverText out;
    GameResult result = view.result.value_or(GameResult{view.winner, "", {}, {}});
    if (result.scores.empty()) {
        for (const SeatView& s : view.seats) {
            result.scores.push_back(s.score);
        }
    }
    out.title = title(view, result.winner);
    out.reason = reason_sentence(view, result);
    out.score = score_line(view, result);
    const bool seated = view.you >= 0;
    // A game that ended because a player left: that seat is on its way to empty (the room
    // state that frees it follows the game_end).
    const bool left = seated && (seat_empty(view) || result.reason == "left");
    out.can_rematch = seated && !rematch_asked && !left;
    out.opponent_left = left;
    if (left) {
        out.waiting = doubles(view) ? "A player left the room: no rematch"
                                    : "Your opponent left the room: no rematch";
    } else if (seated && rematch_asked) {
        out.waiting = rematch_wait(view);
    }
    return out;
}

} // namespace carrom::client
