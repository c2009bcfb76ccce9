#pragma once
// Seats around the board: two in singles (bottom and top); four in doubles, where partners sit
// opposite each other and the turn passes anticlockwise (as seen on screen: bottom, right, top,
// left). Seat indices follow that order, so the next seat is always (seat + 1) % seat_count.

#include "carrom/enum_names.hpp"

#include <cstdint>
#include <string_view>
#include <vector>

namespace carrom::rules {

enum class Side : std::uint8_t { Bottom, Right, Top, Left };
inline constexpr enum_names::Table<Side, 4> kSideNames{{
    {Side::Bottom, "bottom"},
    {Side::Right, "right"},
    {Side::Top, "top"},
    {Side::Left, "left"},
}};

std::string_view to_string(Side side);
bool parse_side(std::string_view text, Side& out);

struct Seat {
    int index = 0;
    Side side = Side::Bottom; // whose baseline the seat shoots from
    int team = 0;             // scores, colours and dues belong to teams; team == seat in singles
    int partner = -1;         // the partner's seat in doubles, -1 in singles
};

// Seats for a match of seat_count (2 or 4) players.
std::vector<Seat> make_seats(int seat_count);
// 2 seats: team = seat; 4 seats: team = seat % 2 (0 and 2 against 1 and 3).
int team_of_seat(int seat, int seat_count);
int team_count(int seat_count);
int next_seat(int seat, int seat_count);

} // namespace carrom::rules
