#include "carrom/client/match_view.hpp"

namespace carrom::client {

const std::string& game_end_name(const GameResult& result) {
    return result.rule.empty() ? result.reason : result.rule;
}

namespace {

bool has_seat(const MatchView& view, int seat) {
    return seat >= 0 && static_cast<std::size_t>(seat) < view.seats.size();
}

} // namespace

std::string seat_name(const MatchView& view, int seat) {
    if (has_seat(view, seat) && !view.seats[static_cast<std::size_t>(seat)].name.empty()) {
        return view.seats[static_cast<std::size_t>(seat)].name;
    }
    return "Seat " + std::to_string(seat + 1);
}

std::string player_name_at_end(const MatchView& view, int seat) {
    if (view.result && seat >= 0 && static_cast<std::size_t>(seat) < view.result->names.size() &&
        !view.result->names[static_cast<std::size_t>(seat)].empty()) {
        return view.result->names[static_cast<std::size_t>(seat)];
    }
    return seat_name(view, seat);
}

int team_of(const MatchView& view, int seat) {
    return has_seat(view, seat) ? rules::team_of_seat(seat, static_cast<int>(view.seats.size()))
                                : -1;
}

std::vector<int> team_seats(const MatchView& view, int team) {
    std::vector<int> out;
    for (int seat = 0; seat < static_cast<int>(view.seats.size()); ++seat) {
        if (team >= 0 && team_of(view, seat) == team) {
            out.push_back(seat);
        }
    }
    return out;
}

int partner_of(const MatchView& view, int seat) {
    const int team = team_of(view, seat);
    for (const int other : team_seats(view, team)) {
        if (other != seat) {
            return other;
        }
    }
    return -1;
}

std::string team_name(const MatchView& view, int team) {
    std::string out;
    for (const int seat : team_seats(view, team)) {
        out += (out.empty() ? "" : " & ") + player_name_at_end(view, seat);
    }
    return out.empty() ? "Team " + std::to_string(team + 1) : out;
}

std::string team_subject(const MatchView& view, int team) {
    return view.seats.size() == 4 ? team_name(view, team) : seat_name(view, team);
}

rules::Side seat_side(const MatchView& view, int seat) {
    if (has_seat(view, seat)) {
        return view.seats[static_cast<std::size_t>(seat)].side;
    }
    // Before a room state: the rules' seats of a singles match.
    return seat == 1 ? rules::Side::Top : rules::Side::Bottom;
}

} // namespace carrom::client
